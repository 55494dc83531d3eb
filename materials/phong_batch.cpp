#include "materials/phong_batch.h"

#include <cstring>

#include "core/accel/simd.h"
#include "core/avx2_clones.h"
#include "materials/lobe_power.h"

namespace rt {

static_assert(kPacketSize == 8, "a batch is one Float8");

namespace {
typedef double Double4 __attribute__((vector_size(32)));
}  // namespace

RT_AVX2_CLONES
void phong_batch(Vec3 kd, Vec3 ks, float shininess, Vec3 n, Vec3 v, const float* dx, const float* dy, const float* dz,
                 unsigned lanes, PhongBatch& out) {
  const Float8 lx = load8(dx), ly = load8(dy), lz = load8(dz);
  const Float8 n_dot_l = lx * n.x + ly * n.y + lz * n.z;
  // reflect(-l, n) = -l - 2 dot(-l, n) n, then its dot with v.
  const Float8 k = 2.0f * ((-lx) * n.x + (-ly) * n.y + (-lz) * n.z);
  const Float8 rx = (-lx) - k * n.x, ry = (-ly) - k * n.y, rz = (-lz) - k * n.z;
  const Float8 r_dot_v = rx * v.x + ry * v.y + rz * v.z;
  // The powers where phong_reflectance asks for one, as lobe_power works them out: by squaring
  // on all lanes at once for a whole exponent, std::pow lane by lane otherwise.
  alignas(32) float cosines[kPacketSize], lit[kPacketSize];
  std::memcpy(cosines, &r_dot_v, sizeof r_dot_v);
  std::memcpy(lit, &n_dot_l, sizeof n_dot_l);
  alignas(32) float power[kPacketSize] = {};
  alignas(32) int32_t has_power[kPacketSize] = {};
  const bool whole = is_whole_exponent(shininess);
  alignas(32) double base[kPacketSize];  // 1 in a lane without a power: no denormal to square
  unsigned squared = 0;                  // the lanes whose power comes from the squarings
  for (int j = 0; j < kPacketSize; ++j) {
    base[j] = 1.0;
    if (!(lanes >> j & 1u) || !(lit[j] > 0.0f) || !(cosines[j] > 0.0f)) continue;
    has_power[j] = -1;
    if (lobe_power_vanishes(cosines[j], shininess)) continue;
    if (whole) {
      base[j] = cosines[j];
      squared |= 1u << j;
    } else {
      power[j] = std::pow(cosines[j], shininess);
    }
  }
  if (squared) {
    Double4 half[2];
    std::memcpy(half, base, sizeof half);
    for (Double4& h : half) h = whole_power(h, static_cast<uint32_t>(shininess));
    std::memcpy(base, half, sizeof half);
    for (int j = 0; j < kPacketSize; ++j)
      if (squared >> j & 1u) power[j] = static_cast<float>(base[j]);
  }
  const Float8 p = load8(power);
  Mask8 with_power;
  std::memcpy(&with_power, has_power, sizeof with_power);
  const Mask8 front = n_dot_l > 0.0f;
  const Float8 zero = splat8(0.0f);
  const auto channel = [&](float d, float s, float* to) {
    const Float8 diffuse = n_dot_l * d;
    Float8 f = with_power ? diffuse + p * s : diffuse;
    f = front ? f : zero;
    std::memcpy(to, &f, sizeof f);
  };
  channel(kd.x, ks.x, out.r);
  channel(kd.y, ks.y, out.g);
  channel(kd.z, ks.z, out.b);
}

}  // namespace rt
