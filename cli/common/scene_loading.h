// How every subcommand asks io for a scene: with the names the render pipeline offers.
#pragma once

#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "io/base/load_options.h"

namespace rt {

// outside_files: --allow-outside-files (LoadLimits::outside_files).
inline LoadOptions cli_load_options(unsigned threads = 0, std::optional<std::string> camera = std::nullopt,
                                    bool outside_files = false, Isa isa = best_isa()) {
  LoadOptions options;
  options.threads = threads;
  options.isa = isa;
  options.integrators = integrators().names();
  options.pixel_samplers = pixel_samplers().names();
  options.camera = std::move(camera);
  options.limits.outside_files = outside_files;
  options.limits.decode_threads = threads;
  return options;
}

}  // namespace rt
