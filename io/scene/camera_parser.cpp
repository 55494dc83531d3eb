#include "io/scene/camera_parser.h"

namespace rt {
namespace {

constexpr NumberRule kFieldOfView{0, 180, true, true, false};
constexpr NumberRule kFisheyeFieldOfView{0, 360, true, false, false};
constexpr NumberRule kShift{-10, 10, false, false, false};
constexpr NumberRule kLatitude{0, 90, false, false, false};
const std::vector<std::string> kProjections = {"perspective", "orthographic", "fisheye", "equirectangular"};
// A scene names a mode to turn stereo on: every name but "none".
// A camera's stereo block names a layout: every mode but "none" (leave the block out for that).
const std::vector<std::string> kStereoLayouts = [] {
  std::vector<std::string> names = kStereoModes.names();
  names.erase(names.begin());
  return names;
}();
const std::vector<std::string> kAnaglyphs = {"dubois", "color"};

void parse_stereo(const JsonReader& r, const Json& v, const std::string& ptr, CameraDescription& c) {
  ObjectReader o(r, v, ptr);
  StereoSettings& s = c.stereo;
  if (const Json* m = o.get("mode", true, join_quoted(kStereoLayouts))) {
    if (const auto k = read_choice(r, *m, o.child("mode"), kStereoLayouts))
      s.mode = *kStereoModes.parse(kStereoLayouts[*k]);
  }
  if (const auto e = o.number("eye_separation", kPositive)) s.eye_separation = static_cast<float>(*e);
  if (const auto d = o.number("convergence", kPositive)) c.convergence = static_cast<float>(*d);
  if (const Json* swap = o.get("swap")) {
    if (swap->is_boolean()) s.swap = swap->get<bool>();
    else r.expected(o.child("swap"), "true or false", *swap);
  }
  if (const Json* a = o.get("anaglyph")) {
    if (const auto k = read_choice(r, *a, o.child("anaglyph"), kAnaglyphs)) s.anaglyph = static_cast<AnaglyphKind>(*k);
  }
  const auto from = o.number("pole_merge_from", kLatitude), to = o.number("pole_merge_to", kLatitude);
  if (from) s.pole_merge_from = radians(static_cast<float>(*from));
  if (to) s.pole_merge_to = radians(static_cast<float>(*to));
  o.finish();
  if (s.pole_merge_to < s.pole_merge_from)
    r.error(o.child(to ? "pole_merge_to" : "pole_merge_from"),
            "expected pole_merge_from <= pole_merge_to (degrees of latitude: the eye separation fades between them)");
}

// Each eye sits half the separation off the camera and turns its view by half the separation over
// the convergence distance (Camera::eye_camera). Both must stay far inside single precision, or the
// eyes' rays are infinite or NaN: 1e-45 passes "> 0" as a denormal and makes the turn infinite.
// A turn of kMaxEyeTurn (the convergence plane 1/20000 of the separation away) is far past any
// viewable pair, and its rays' directions still normalise exactly.
constexpr float kMaxEyeTurn = 1e4f;

void check_eyes(const JsonReader& r, const std::string& ptr, const CameraDescription& c) {
  const float half = 0.5f * c.stereo.eye_separation;
  const float convergence = c.convergence.value_or(c.focus_distance.value_or(glm::length(c.look_at - c.position)));
  const float turn = half / convergence;
  const bool has_convergence = c.convergence.has_value();
  if (!(std::isfinite(turn) && turn <= kMaxEyeTurn)) {
    r.error(ptr + (has_convergence ? "/convergence" : "/eye_separation"),
            "expected eye_separation / convergence at most " + format_number(2.0 * kMaxEyeTurn) +
                " (each eye turns its view by half of it), found " + format_number(c.stereo.eye_separation) + " / " +
                format_number(convergence) +
                (has_convergence ? "" : " (the convergence defaults to the focus distance)"));
  } else if (!std::isfinite(max_abs_component(c.position) + half)) {
    r.error(ptr + "/eye_separation", "expected the eyes to fit in single precision (|x| < 3.4e38), found an eye at " +
                                         format_number(max_abs_component(c.position)) + " + " + format_number(half));
  }
}

}  // namespace

void parse_camera(const JsonReader& r, const Json& v, const std::string& pointer, CameraDescription& c) {
  ObjectReader o(r, v, pointer);
  const auto position = o.vec3("position", true);
  const auto look_at = o.vec3("look_at", true);
  const auto up = o.vec3("up");
  if (const Json* p = o.get("projection")) {
    if (const auto k = read_choice(r, *p, o.child("projection"), kProjections))
      c.projection = static_cast<CameraProjection>(*k);
  }
  const bool fisheye = c.projection == CameraProjection::kFisheye;
  const auto fov = o.number("fov", fisheye ? kFisheyeFieldOfView : kFieldOfView);
  const auto aperture = o.number("aperture", kNonNegative);
  const auto focus = o.number("focus_distance", kPositive);
  const auto width = o.number("width", kPositive);
  if (const Json* s = o.get("shift")) {
    if (!s->is_array() || s->size() != 2) {
      r.expected(o.child("shift"), "[x, y]: the window's shift in units of the image's larger side", *s);
    } else {
      const auto x = read_number(r, (*s)[0], o.child("shift") + "/0", kShift);
      const auto y = read_number(r, (*s)[1], o.child("shift") + "/1", kShift);
      if (x && y) c.shift = Vec2(static_cast<float>(*x), static_cast<float>(*y));
    }
  }
  if (const Json* s = o.get("stereo")) parse_stereo(r, *s, o.child("stereo"), c);
  o.finish();
  if (aperture) c.aperture = static_cast<float>(*aperture);
  if (focus) c.focus_distance = static_cast<float>(*focus);
  if (position) c.position = *position;
  if (look_at) c.look_at = *look_at;
  if (up) c.up = *up;
  if (fov) c.fov_degrees = static_cast<float>(*fov);
  else if (fisheye) c.fov_degrees = 180.0f;
  if (width) c.ortho_width = static_cast<float>(*width);

  // Keys that do nothing with this projection say so, rather than being silently ignored.
  const auto unused = [&](const char* key, const char* why) {
    if (o.has(key)) r.warning(o.child(key), std::string("this does nothing here: ") + why, Anchor::kKey);
  };
  const std::string projection = kProjections[static_cast<size_t>(c.projection)];
  if (c.projection != CameraProjection::kPerspective && c.aperture > 0.0f)
    unused("aperture", "depth of field needs a perspective camera");
  if (c.projection != CameraProjection::kOrthographic)
    unused("width", "\"width\" sizes an orthographic camera's view (\"fov\" the others')");
  if (c.projection == CameraProjection::kOrthographic || c.projection == CameraProjection::kEquirectangular)
    unused("fov", "an orthographic view is \"width\" wide, an equirectangular one always 360 x 180 degrees");
  if (c.projection == CameraProjection::kFisheye || c.projection == CameraProjection::kEquirectangular)
    unused("shift", "only perspective and orthographic cameras shift their window");
  if (c.stereo.enabled() && c.projection == CameraProjection::kOrthographic)
    r.error(o.child("stereo"),
            "expected a perspective, fisheye or equirectangular camera for stereo, found an orthographic one (parallel "
            "rays see no depth)",
            Anchor::kKey);
  (void)projection;

  if (!position || !look_at) return;
  const Vec3 forward = c.look_at - c.position;
  if (glm::length(forward) < 1e-6f * std::max(1.0f, max_abs_component(c.position))) {
    r.error(o.child("look_at"), "expected a point away from the camera position, found the position itself");
    return;
  }
  if (c.stereo.enabled()) check_eyes(r, o.child("stereo"), c);
  if (!(glm::length(c.up) > 0.0f) || glm::length(glm::cross(glm::normalize(forward), glm::normalize(c.up))) < 1e-4f) {
    r.error(up ? o.child("up") : o.child("look_at"),
            "expected an up direction not parallel to the viewing direction, found one parallel to it");
  }
}

Camera make_camera(const CameraDescription& c) {
  Camera camera = Camera::look_at(c.position, c.look_at, c.up, c.fov_degrees);
  camera.aperture = c.aperture;
  camera.focus_distance = c.focus_distance.value_or(glm::length(c.look_at - c.position));
  camera.projection = c.projection;
  camera.ortho_width = c.ortho_width;
  camera.fisheye_fov = radians(c.fov_degrees);
  camera.shift = c.shift;
  camera.stereo = c.stereo;
  camera.stereo.convergence = c.convergence.value_or(camera.focus_distance);
  return camera;
}

}  // namespace rt
