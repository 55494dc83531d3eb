// A packet's pinhole rays (core/render/camera_ray_batch.h) are generate_ray's, bit for bit: several
// cameras (wide and tall images, a shifted window, a stereo eye's offset), full and partial
// packets, points across the image and beyond its edges.
#include <catch2/catch.hpp>

#include <cstring>

#include "core/render/camera_ray_batch.h"
#include "core/rng.h"

using namespace rt;

namespace {

bool same_bits(Vec3 a, Vec3 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("a packet of pinhole rays is generate_ray's, bit for bit", "[camera][batch]") {
  Camera wide = Camera::look_at({0.3f, 2.6f, 9.5f}, {0.0f, 0.9f, 0.0f}, {0, 1, 0}, 40.0f);
  Camera shifted = Camera::look_at({-4.0f, 1.0f, 2.0f}, {1.0f, 0.5f, -3.0f}, {0, 1, 0}, 73.0f);
  shifted.shift = Vec2(0.17f, -0.05f);
  Camera eye = wide.eye_camera(-1);
  eye.window_offset = 0.031f;  // as an off-axis stereo eye's
  const struct {
    const Camera* camera;
    int width, height;
  } cases[] = {{&wide, 1920, 1440}, {&wide, 333, 777}, {&shifted, 160, 120}, {&eye, 801, 451}};
  Rng rng(7);
  int rays = 0;
  for (const auto& c : cases) {
    REQUIRE(batches_camera_rays(*c.camera));
    for (int count = 1; count <= kCameraRayBatch; ++count)
      for (int round = 0; round < 64; ++round) {
        float x[kCameraRayBatch], y[kCameraRayBatch];
        for (int j = 0; j < count; ++j) {
          // Across the image and a little beyond it (crop windows, filters).
          x[j] = (rng.next_float() * 1.2f - 0.1f) * static_cast<float>(c.width);
          y[j] = (rng.next_float() * 1.2f - 0.1f) * static_cast<float>(c.height);
        }
        Ray out[kCameraRayBatch];
        perspective_ray_batch(*c.camera, x, y, count, c.width, c.height, out);
        for (int j = 0; j < count; ++j) {
          const Ray one = c.camera->generate_ray(x[j], y[j], c.width, c.height);
          INFO("camera " << (&c - cases) << ", point (" << x[j] << ", " << y[j] << ")");
          REQUIRE(same_bits(out[j].origin, one.origin));
          REQUIRE(same_bits(out[j].direction, one.direction));
          REQUIRE(out[j].tmin == one.tmin);
          REQUIRE(out[j].tmax == one.tmax);
          ++rays;
        }
      }
  }
  CHECK(rays == 4 * 64 * (kCameraRayBatch * (kCameraRayBatch + 1) / 2));
}

TEST_CASE("only a perspective pinhole's rays are batched", "[camera][batch]") {
  Camera c = Camera::look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0f);
  CHECK(batches_camera_rays(c));
  c.aperture = 0.1f;
  CHECK_FALSE(batches_camera_rays(c));
  c.aperture = 0.0f;
  for (CameraProjection p :
       {CameraProjection::kOrthographic, CameraProjection::kFisheye, CameraProjection::kEquirectangular}) {
    c.projection = p;
    CHECK_FALSE(batches_camera_rays(c));
  }
}
