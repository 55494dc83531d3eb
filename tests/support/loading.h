// Load options as rtcli uses them: one BVH build thread and the renderer's integrator names.
#pragma once

#include "core/render/integrator.h"
#include "io/load_options.h"

namespace rt::test {

inline LoadOptions load_options(unsigned threads = 1) { return LoadOptions{threads, integrator_names(), LoadLimits{}}; }

}  // namespace rt::test
