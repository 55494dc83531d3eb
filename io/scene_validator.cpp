#include "io/scene_validator.h"

#include "io/scene_loader.h"

namespace rt {

Diagnostics validate_file(const std::string& path, const LoadOptions& options_in) {
  LoadOptions options = options_in;
  options.build_bvh = false;
  Diagnostics diags;
  load_scene(path, options, diags);
  return diags;
}

}  // namespace rt
