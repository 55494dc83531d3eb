// The projections and stereo eyes: orthographic rays are parallel, an equirectangular image's
// edges meet, a fisheye's angle grows with the radius; a point at the convergence distance has no
// disparity and a nearer one the disparity worked out by hand; ODS eyes sit on the viewing
// circle and merge at the poles; the left eye is the mono render from its place; Dubois' matrices.
#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "core/render/stereo_images.h"
#include "io/scene_loader.h"
#include "tests/support/geometry.h"
#include "tests/support/loading.h"
#include "tests/support/test_paths.h"

using namespace rt;
using rt::test::check_vec;

namespace {

constexpr int kW = 64, kH = 32;

Camera camera(CameraProjection p) {
  Camera c = Camera::look_at({0, 1, 5}, {0, 1, 0}, {0, 1, 0}, 50.0f);
  c.projection = p;
  return c;
}

// The continuous pixel x at which a perspective camera sees world point p.
float pixel_x(const Camera& c, Vec3 p) {
  const Vec3 d = p - c.position;
  const float sx = glm::dot(d, c.right) / glm::dot(d, c.forward) - c.window_offset;
  const float aspect = static_cast<float>(kW) / static_cast<float>(kH);
  return (sx / (c.tan_half_fov * aspect) + 1.0f) * 0.5f * static_cast<float>(kW);
}

}  // namespace

TEST_CASE("cameras: orthographic rays are parallel, from a window `width` wide", "[camera]") {
  Camera c = camera(CameraProjection::kOrthographic);
  c.ortho_width = 4.0f;
  const Ray a = c.generate_ray(0.0f, 16.0f, kW, kH), b = c.generate_ray(64.0f, 16.0f, kW, kH);
  check_vec(a.direction, c.forward);
  check_vec(b.direction, c.forward);
  CHECK(glm::length(b.origin - a.origin) == Approx(4.0f));
  const Ray top = c.generate_ray(32.0f, 0.0f, kW, kH);
  CHECK(glm::dot(top.origin - c.position, c.up) == Approx(1.0f));  // half the height: 4 / 2 / 2
  // The ray cone starts one pixel wide and does not spread.
  CHECK(c.pixel_footprint(kW, kH) == Approx(4.0f / kW));
  CHECK(c.pixel_spread(kW, kH) == 0.0f);
  // Aperture does nothing but on a perspective camera.
  c.aperture = 0.5f;
  CHECK(c.generate_ray(10.0f, 10.0f, kW, kH, Vec2(0.9f, 0.2f)).origin == c.generate_ray(10.0f, 10.0f, kW, kH).origin);
}

TEST_CASE("cameras: an equirectangular image's left and right edges meet, centre ahead, top up", "[camera]") {
  const Camera c = camera(CameraProjection::kEquirectangular);
  for (const float y : {1.5f, 8.0f, 16.0f, 30.5f})
    check_vec(c.generate_ray(0.0f, y, kW, kH).direction, c.generate_ray(static_cast<float>(kW), y, kW, kH).direction);
  check_vec(c.generate_ray(32.0f, 16.0f, kW, kH).direction, c.forward);
  check_vec(c.generate_ray(48.0f, 16.0f, kW, kH).direction, c.right);  // a quarter turn to the right
  check_vec(c.generate_ray(0.0f, 16.0f, kW, kH).direction, -c.forward);
  check_vec(c.generate_ray(20.0f, 0.0f, kW, kH).direction, c.up);
  check_vec(c.generate_ray(20.0f, 32.0f, kW, kH).direction, -c.up);
  // Adjacent columns 0 and W - 1 look 2 pi / W apart across the seam, as any two neighbours.
  const Vec3 first = c.generate_ray(0.5f, 16.0f, kW, kH).direction,
             last = c.generate_ray(63.5f, 16.0f, kW, kH).direction;
  CHECK(std::acos(glm::dot(first, last)) == Approx(2.0f * kPi / kW).epsilon(1e-3));
}

TEST_CASE("cameras: an equidistant fisheye's angle grows with the radius, outside its circle, nothing", "[camera]") {
  Camera c = camera(CameraProjection::kFisheye);
  c.fisheye_fov = radians(180.0f);
  check_vec(c.generate_ray(32.0f, 16.0f, kW, kH).direction, c.forward);
  check_vec(c.generate_ray(48.0f, 16.0f, kW, kH).direction, c.right);  // the circle's edge: 90 degrees
  const Vec3 halfway = c.generate_ray(32.0f, 8.0f, kW, kH).direction;  // half the radius up: 45 degrees
  CHECK(glm::dot(halfway, c.forward) == Approx(std::cos(kPi / 4)));
  CHECK(glm::dot(halfway, c.up) == Approx(std::sin(kPi / 4)));
  CHECK(c.sees(32.0f, 16.0f, kW, kH));
  CHECK_FALSE(c.sees(2.0f, 2.0f, kW, kH));
  c.fisheye_fov = radians(360.0f);
  check_vec(c.generate_ray(48.0f, 16.0f, kW, kH).direction, -c.forward, 1e-4);
}

TEST_CASE("stereo: the convergence plane has no disparity, a nearer point the disparity by hand", "[camera][stereo]") {
  Camera c = camera(CameraProjection::kPerspective);
  c.stereo.mode = StereoMode::kAnaglyph;
  c.stereo.eye_separation = 0.2f;
  c.stereo.convergence = 5.0f;
  const Camera left = c.eye_camera(-1), right = c.eye_camera(1);
  // Parallel axes: no toe-in, and no vertical parallax.
  check_vec(left.forward, c.forward);
  check_vec(right.forward, c.forward);
  check_vec(left.position, c.position - 0.1f * c.right);
  const Vec3 on_plane = c.position + 5.0f * c.forward + 0.7f * c.right + 0.3f * c.up;
  CHECK(pixel_x(left, on_plane) - pixel_x(right, on_plane) == Approx(0.0f).margin(1e-3));
  // pixel_x inverts generate_ray: the ray through that pixel passes through the point.
  const Ray through =
      left.generate_ray(pixel_x(left, on_plane), 16.0f - 0.3f / (5.0f * c.tan_half_fov) * 16.0f, kW, kH);
  const Vec3 to = on_plane - through.origin;
  CHECK(glm::length(glm::cross(to, through.direction)) / glm::length(to) == Approx(0.0f).margin(1e-4));
  // At depth Z = 2: disparity s (1/Z - 1/C) W / (2 tan_half aspect), crossed (left image to the right).
  const Vec3 near = c.position + 2.0f * c.forward;
  const float aspect = static_cast<float>(kW) / static_cast<float>(kH);
  const float by_hand = 0.2f * (1.0f / 2.0f - 1.0f / 5.0f) * kW / (2.0f * c.tan_half_fov * aspect);
  CHECK(pixel_x(left, near) - pixel_x(right, near) == Approx(by_hand).epsilon(1e-4));
}

TEST_CASE("stereo: ODS eyes sit on the viewing circle, merging towards the poles", "[camera][stereo]") {
  Camera c = camera(CameraProjection::kEquirectangular);
  c.stereo.mode = StereoMode::kTopBottom;
  c.stereo.eye_separation = 0.064f;
  c.stereo.convergence = 1e30f;  // parallel: directions as the mono camera's
  const Camera left = c.eye_camera(-1), right = c.eye_camera(1);
  for (const float x : {0.5f, 16.0f, 32.0f, 50.0f}) {
    const Ray l = left.generate_ray(x, 16.0f, kW, kH), r = right.generate_ray(x, 16.0f, kW, kH);
    CHECK(glm::length(r.origin - c.position) == Approx(0.032f));                       // on the circle of radius s / 2
    CHECK(glm::dot(r.origin - c.position, r.direction) == Approx(0.0f).margin(1e-6));  // tangent to it
    check_vec(l.origin - c.position, -(r.origin - c.position));
    // The right eye on the right of the direction it looks in.
    CHECK(glm::dot(glm::cross(r.direction, c.up), r.origin - c.position) == Approx(0.032f));
  }
  // Looking straight ahead, the right eye is to the right.
  check_vec(right.generate_ray(32.0f, 16.0f, kW, kH).origin, c.position + 0.032f * c.right);
  // Latitude 67.5 (between 60 and 75): cos(pi / 4) of the offset; 80 degrees: none.
  const float y_67 = 16.0f - 67.5f / 90.0f * 16.0f, y_80 = 16.0f - 80.0f / 90.0f * 16.0f;
  CHECK(glm::length(right.generate_ray(10.0f, y_67, kW, kH).origin - c.position) ==
        Approx(0.032f * std::cos(kPi / 4)).epsilon(1e-3));
  CHECK(right.generate_ray(10.0f, y_80, kW, kH).origin == c.position);
}

TEST_CASE("stereo: the left eye is the mono render from the left eye's place and window", "[camera][stereo]") {
  Scene scene;
  auto assets = std::make_shared<SceneAssets>();
  Material m;
  m.kd = Vec3(0.7f, 0.3f, 0.2f);
  m.glossy = 0.2f;
  m.reflectivity = Vec3(0.3f);
  assets->materials = {m};
  scene.assets = assets;
  scene.lights = {RectLight{{-1, 4, -1}, {2, 0, 0}, {0, 0, 2}, Vec3(1.0f), {}, true}};
  PrimitiveSet prims;
  prims.shapes.push_back(AnalyticShape{ShapeKind::kSphere, 0, *make_transform(Mat4(1.0f))});
  prims.shapes.push_back(AnalyticShape{ShapeKind::kCube, 0, *make_transform(compose_trs({0, -2, 0}, {}, {3, 1, 3}))});
  scene.bvh = Bvh(prims, {});
  scene.camera = Camera::look_at({0, 1, 5}, {0, 0, 0}, {0, 1, 0}, 40.0f);
  scene.camera.stereo.mode = StereoMode::kSideBySide;
  scene.camera.stereo.convergence = 5.0f;
  RenderSettings settings;
  settings.width = 48;
  settings.height = 32;
  settings.threads = 2;
  const Camera left = scene.camera.eye_camera(-1), right = scene.camera.eye_camera(1);
  Image left_image, right_image, mono_image;
  render(scene, settings, left_image, {}, 0, RenderView{&left, 0, {}});
  render(scene, settings, right_image, {}, 0, RenderView{&right, 1, {}});
  Scene mono = scene;
  mono.camera = left;
  render(mono, settings, mono_image);
  CHECK(left_image.pixels == mono_image.pixels);
  CHECK(left_image.pixels != right_image.pixels);
  // Side by side: the left eye on the left; swapped (cross-eyed), on the right.
  StereoSettings s = scene.camera.stereo;
  const Image sbs = compose_stereo(left_image, right_image, s);
  CHECK(sbs.width == 96);
  CHECK(sbs.at(5, 7) == left_image.at(5, 7));
  CHECK(sbs.at(48 + 5, 7) == right_image.at(5, 7));
  s.swap = true;
  CHECK(compose_stereo(left_image, right_image, s).at(5, 7) == right_image.at(5, 7));
  s.mode = StereoMode::kTopBottom;
  s.swap = false;
  const Image tb = compose_stereo(left_image, right_image, s);
  CHECK(tb.height == 64);
  CHECK(tb.at(5, 32 + 7) == right_image.at(5, 7));
}

TEST_CASE("stereo: Dubois' red-cyan matrices on known colours", "[stereo]") {
  // White in both eyes stays (nearly) white: each row of the two matrices sums to about 1.
  const Vec3 white = anaglyph_pixel(Vec3(1.0f), Vec3(1.0f), AnaglyphKind::kDubois);
  CHECK(white.r == Approx(0.999f));
  CHECK(white.g == Approx(1.0f));
  CHECK(white.b == Approx(1.0f));
  // Red seen by the left eye alone: its first column, negatives clamped.
  const Vec3 red = anaglyph_pixel(Vec3(1, 0, 0), Vec3(0.0f), AnaglyphKind::kDubois);
  CHECK(red.r == Approx(0.456f));
  CHECK(red.g == 0.0f);
  CHECK(red.b == 0.0f);
  // Blue seen by the right eye alone: 1.226 in blue, clamped to 1; -0.002 red clamped to 0.
  const Vec3 blue = anaglyph_pixel(Vec3(0.0f), Vec3(0, 0, 1), AnaglyphKind::kDubois);
  CHECK(blue == Vec3(0.0f, 0.0f, 1.0f));
  // Grey 0.5 in the left eye, green in the right: r = 0.5 * 1.132 - 0.088, g = -0.047 + 0.734.
  const Vec3 mix = anaglyph_pixel(Vec3(0.5f), Vec3(0, 1, 0), AnaglyphKind::kDubois);
  CHECK(mix.r == Approx(0.5f * 1.132f - 0.088f));
  CHECK(mix.g == Approx(-0.047f + 0.734f));
  CHECK(mix.b == Approx(0.0f).margin(1e-6));  // -0.0205 - 0.113, clamped
  // The colour anaglyph: red from the left, green and blue from the right.
  CHECK(anaglyph_pixel(Vec3(0.2f, 0.4f, 0.6f), Vec3(0.9f, 0.8f, 0.7f), AnaglyphKind::kColor) == Vec3(0.2f, 0.8f, 0.7f));
}

TEST_CASE("cameras: a glTF orthographic camera is orthographic, xmag its half width", "[camera][gltf]") {
  if (!rt::test::have_sample_models()) return;
  LoadOptions options = rt::test::load_options();
  options.camera = "camera 1";  // Cameras.gltf's second camera: orthographic, xmag 1
  Diagnostics diags;
  const auto loaded = load_scene(rt::test::sample_model("Cameras/glTF/Cameras.gltf"), options, diags);
  REQUIRE(loaded);
  CHECK(diags.all().empty());  // no "rendered as a perspective camera" warning
  const Camera& c = loaded->scene.camera;
  CHECK(c.projection == CameraProjection::kOrthographic);
  CHECK(c.ortho_width == Approx(2.0f));
  check_vec(c.generate_ray(0.0f, 50.0f, 100, 100).direction, c.generate_ray(100.0f, 50.0f, 100, 100).direction);
}

TEST_CASE("stereo: a glTF model on its own converges on the model", "[camera][stereo][gltf]") {
  Diagnostics diags;
  const auto loaded = load_scene(rt::test::source_path("scenes/models/knot.glb"), rt::test::load_options(), diags);
  REQUIRE(loaded);
  const Camera& c = loaded->scene.camera;
  // The framing camera looks at the model's centre: the convergence plane passes through it.
  const Vec3 centre = loaded->scene.bvh.bounds().centre();
  CHECK(c.stereo.convergence == Approx(glm::length(centre - c.position)).epsilon(1e-3));
}
