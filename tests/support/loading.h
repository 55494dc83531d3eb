// Load options as rtcli uses them (one BVH build thread and the renderer's integrator names), and
// scenes written by tests as text.
#pragma once

#include <string>

#include <catch2/catch.hpp>

#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "io/base/load_options.h"
#include "io/scene_loader.h"
#include "tests/support/test_paths.h"

namespace rt::test {

inline LoadOptions load_options(unsigned threads = 1) {
  LoadOptions options;
  options.threads = threads;
  options.integrators = integrators().names();
  options.pixel_samplers = pixel_samplers().names();
  return options;
}

// Loads the scene file at `path`; the test stops (showing every diagnostic) if it does not load.
inline LoadedScene load_scene_file(const std::string& path) {
  Diagnostics diags;
  auto loaded = load_scene(path, load_options(), diags);
  for (const Diagnostic& d : diags.all()) UNSCOPED_INFO(format_diagnostic(d));
  REQUIRE(loaded);
  return std::move(*loaded);
}

// Writes `json` to the scratch folder as `name` and loads it; the test stops (showing every
// diagnostic) if it does not load.
inline LoadedScene load_scene_text(const std::string& name, const std::string& json) {
  Diagnostics diags;
  auto loaded = load_scene(write_file(name, json), load_options(), diags);
  for (const Diagnostic& d : diags.all()) UNSCOPED_INFO(format_diagnostic(d));
  REQUIRE(loaded);
  return std::move(*loaded);
}

}  // namespace rt::test
