#include <catch2/catch.hpp>

#include <bit>
#include <cstring>

#include "core/rng.h"
#include "materials/lobe_power.h"
#include "materials/phong.h"
#include "materials/phong_batch.h"

using namespace rt;

namespace {

bool same_bits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }

float unit(uint64_t& state) { return static_cast<float>(mix64(++state) >> 40) * 0x1p-24f; }

Vec3 random_direction(uint64_t& state) {
  for (;;) {
    const Vec3 v(2.0f * unit(state) - 1.0f, 2.0f * unit(state) - 1.0f, 2.0f * unit(state) - 1.0f);
    const float length2 = glm::dot(v, v);
    if (length2 > 1e-4f && length2 <= 1.0f) return glm::normalize(v);
  }
}

}  // namespace

TEST_CASE("lobe_power: the correctly rounded power of a whole exponent, std::pow's otherwise", "[materials]") {
  // Every 4099th float in (0, 1] and exponents from 0 to far past any shininess. A whole exponent
  // in [1, 65536] is raised by squaring: the power correctly rounded, as double precision's pow
  // rounded to float gives it (its error is far below a float's), and within a unit of powf's
  // (glibc's is within 0.82). The skipped powers are zeros that powf itself returns (most of
  // them, with a narrow lobe), never more.
  const float exponents[] = {0.0f,   0.5f,   1.0f,   2.0f,   3.3f,    8.0f, 20.0f,    40.0f,    90.0f,
                             150.0f, 151.0f, 300.0f, 400.0f, 1000.0f, 1e4f, 65536.0f, 65537.0f, 1e6f};
  long zeros = 0, tested = 0, squared = 0, not_rounded = 0, far_from_powf = 0, differ = 0;
  for (const float exponent : exponents)
    for (uint32_t bits = 1; bits <= std::bit_cast<uint32_t>(1.0f); bits += 4099) {
      const float c = std::bit_cast<float>(bits);
      const float power = lobe_power(c, exponent);
      const float powf = std::pow(c, exponent);
      ++tested;
      if (power == 0.0f) ++zeros;
      if (!is_whole_exponent(exponent)) {
        if (!same_bits(power, powf)) ++differ;
        continue;
      }
      ++squared;
      const auto rounded = static_cast<float>(std::pow(static_cast<double>(c), static_cast<double>(exponent)));
      if (!same_bits(power, rounded)) ++not_rounded;
      const auto units_apart = std::bit_cast<int32_t>(power) - std::bit_cast<int32_t>(powf);
      if (units_apart < -1 || units_apart > 1) ++far_from_powf;
    }
  CHECK(differ == 0);
  CHECK(squared > tested / 2);
  CHECK(not_rounded == 0);
  CHECK(far_from_powf == 0);
  CHECK(zeros > tested / 2);  // the early answer is taken: most of (0, 1] underflows at 300 and beyond
  CHECK(is_whole_exponent(300.0f));
  CHECK_FALSE(is_whole_exponent(0.0f));
  CHECK_FALSE(is_whole_exponent(3.3f));
  CHECK_FALSE(is_whole_exponent(65537.0f));
  CHECK(lobe_power(0.5f, 2.0f) == 0.25f);
  CHECK(lobe_power(0.5f, 300.0f) == 0.0f);
  CHECK(lobe_power(0.99f, 300.0f) == std::pow(0.99f, 300.0f));
  CHECK(lobe_power(0.99f, 300.0f) > 0.04f);
}

TEST_CASE("phong_batch: phong_reflectance's floats, lane by lane", "[materials]") {
  uint64_t state = 7;
  for (int round = 0; round < 2000; ++round) {
    const Vec3 n = random_direction(state), v = random_direction(state);
    const Vec3 kd(unit(state), unit(state), unit(state)), ks(unit(state), unit(state), unit(state));
    const float shininess = round % 3 == 0 ? 300.0f : 1.0f + 100.0f * unit(state);
    alignas(32) float dx[kPacketSize], dy[kPacketSize], dz[kPacketSize];
    Vec3 l[kPacketSize];
    for (int j = 0; j < kPacketSize; ++j) {
      // Some near the mirror direction, so the specular lobe's powers are not all zeros.
      l[j] = j % 2 == 0 ? random_direction(state) : glm::normalize(reflect(-v, n) + 0.1f * random_direction(state));
      dx[j] = l[j].x;
      dy[j] = l[j].y;
      dz[j] = l[j].z;
    }
    const unsigned lanes = static_cast<unsigned>(mix64(++state)) & 0xffu;
    PhongBatch batch;
    phong_batch(kd, ks, shininess, n, v, dx, dy, dz, lanes, batch);
    for (int j = 0; j < kPacketSize; ++j) {
      if (!(lanes >> j & 1u)) continue;
      const Vec3 one = phong_reflectance(kd, ks, shininess, n, l[j], v);
      INFO("round " << round << " lane " << j);
      CHECK(same_bits(batch[j].x, one.x));
      CHECK(same_bits(batch[j].y, one.y));
      CHECK(same_bits(batch[j].z, one.z));
    }
  }
}

TEST_CASE("add_lit: Vec3 arithmetic's sum, sample after sample", "[materials]") {
  uint64_t state = 11;
  for (int round = 0; round < 2000; ++round) {
    PhongBatch batch;
    alignas(32) float scale[kPacketSize];
    for (int j = 0; j < kPacketSize; ++j) {
      batch.r[j] = unit(state);
      batch.g[j] = unit(state);
      batch.b[j] = unit(state);
      scale[j] = 10.0f * unit(state);
    }
    const Vec3 color(unit(state), unit(state), unit(state));
    const unsigned lanes = static_cast<unsigned>(mix64(++state)) & 0xffu;
    const Vec3 start(unit(state), unit(state), unit(state));
    Vec3 one_by_one = start, batched = start;
    for (int j = 0; j < kPacketSize; ++j)
      if (lanes >> j & 1u) one_by_one += color * scale[j] * batch[j];
    add_lit(batch, color, scale, lanes, batched);
    INFO("round " << round);
    CHECK(same_bits(batched.x, one_by_one.x));
    CHECK(same_bits(batched.y, one_by_one.y));
    CHECK(same_bits(batched.z, one_by_one.z));
  }
}
