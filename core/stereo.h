// How a camera makes an image for two eyes (docs/scene-format.md, "Stereo"): which layout, how far
// apart the eyes are, where the plane of zero parallax lies. The render pipeline renders each eye
// with Camera::eye_camera and core/render/stereo_images.h puts the two images together.
#pragma once

#include <array>
#include <cstdint>

#include "core/math.h"
#include "core/name_table.h"

namespace rt {

enum class StereoMode : uint8_t { kNone, kAnaglyph, kSideBySide, kTopBottom, kPair };
// Their names in scene files, --stereo and --stats.
inline constexpr NameEntry<StereoMode> kStereoModeEntries[] = {
    {"none", StereoMode::kNone, "one view (the left eye's, or the camera's)"},
    {"anaglyph", StereoMode::kAnaglyph, "red-cyan"},
    {"side_by_side", StereoMode::kSideBySide, "left eye on the left"},
    {"top_bottom", StereoMode::kTopBottom, "left eye on top"},
    {"pair", StereoMode::kPair, "NAME-left and NAME-right"}};
inline constexpr NameTable<StereoMode> kStereoModes{kStereoModeEntries};
enum class AnaglyphKind : uint8_t { kDubois, kColor };

struct StereoSettings {
  StereoMode mode = StereoMode::kNone;
  float eye_separation = 0.064f;  // metres (scene units) between the eyes
  float convergence = 1.0f;       // distance to the plane of zero parallax; io defaults it to the focus distance
  bool swap = false;              // right eye first: cross-eyed side by side, right on top
  AnaglyphKind anaglyph = AnaglyphKind::kDubois;
  // Omni-directional stereo: the eye separation fades (by a cosine) from `pole_merge_from` to 0 at
  // `pole_merge_to` degrees of latitude, so that the poles do not swirl (Cycles' pole merge).
  float pole_merge_from = radians(60.0f);
  float pole_merge_to = radians(75.0f);

  bool enabled() const { return mode != StereoMode::kNone; }
};

}  // namespace rt
