// Display view transforms from an OpenColorIO config (Debian's libopencolorio 2.1, BSD-3-Clause):
// the scene-linear radiance a render makes (linear Rec.709, OCIO's scene_linear role in Blender's
// config) turned into a display's encoded values by a view (Blender's "Standard", "Filmic", and in
// Blender 4's config "AgX") and optional looks ("Medium High Contrast"), exactly as Blender shows a
// render with the same config. rtcli carries no config: the user names one (--ocio-config), or
// Blender's own is found where Debian installs it (kBlenderConfigs).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/image.h"

namespace rt {

// Where Debian's and Blender's own builds keep Blender's config, tried in order.
extern const char* const kBlenderConfigs[];

class ViewTransform {
 public:
  // The view `view` (matched without regard to case) of the config's default display, with
  // `looks` ("" for none). Null, with the reason in `error` (the views or looks there are), when
  // the config cannot be read or has no such view or look.
  static std::shared_ptr<const ViewTransform> open(const std::string& config_path, const std::string& view,
                                                   const std::string& looks, std::string& error);
  // The first of kBlenderConfigs that exists, or "".
  static std::string blender_config();

  // Every pixel through the view, in place: display-encoded values (clamped to [0, 1]).
  void apply(std::vector<Vec3>& pixels) const;
  // "Filmic (sRGB display, look Medium High Contrast) from /path/config.ocio"
  const std::string& description() const { return description_; }

  ~ViewTransform();
  ViewTransform(const ViewTransform&) = delete;
  ViewTransform& operator=(const ViewTransform&) = delete;

 private:
  ViewTransform();
  struct Processor;
  std::unique_ptr<Processor> processor_;
  std::string description_;
};

}  // namespace rt
