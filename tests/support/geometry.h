// Small helpers shared by the geometry tests.
#pragma once

#include <catch2/catch.hpp>

#include "core/ray.h"

namespace rt::test {

inline Ray make_ray(Vec3 origin, Vec3 direction) {
  Ray r;
  r.origin = origin;
  r.direction = direction;
  return r;
}

inline void check_vec(Vec3 a, Vec3 b, double margin = 1e-5) {
  CHECK(a.x == Approx(b.x).margin(margin));
  CHECK(a.y == Approx(b.y).margin(margin));
  CHECK(a.z == Approx(b.z).margin(margin));
}

}  // namespace rt::test
