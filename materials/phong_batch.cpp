#include "materials/phong_batch.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "core/avx2_clones.h"
#include "core/simd.h"
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
  const Mask8 lane_bits = {1, 2, 4, 8, 16, 32, 64, 128};
  const Mask8 with_power = ((static_cast<int32_t>(lanes) & lane_bits) != 0) & (n_dot_l > 0.0f) & (r_dot_v > 0.0f);
  // lobe_power_vanishes, lane by lane: the same operations on the same floats.
  const Mask8 bits = reinterpret_cast<Mask8>(r_dot_v);
  const Float8 e = __builtin_convertvector((bits >> 23) - 127, Float8);
  const Float8 m = __builtin_convertvector(bits & 0x7fffff, Float8) * 0x1p-23f;
  const Mask8 vanishes =
      (r_dot_v >= std::numeric_limits<float>::min()) & (splat8(shininess) * (e + 1.4427f * m) < -151.0f);
  const Mask8 raised = with_power & ~vanishes;
  Float8 p = splat8(0.0f);
  if (is_whole_exponent(shininess)) {
    // 1 in a lane without a power: no denormal to square.
    const Float8 c = raised ? r_dot_v : splat8(1.0f);
    const auto exponent = static_cast<uint32_t>(shininess);
    const Double4 lo =
        whole_power(__builtin_convertvector(__builtin_shufflevector(c, c, 0, 1, 2, 3), Double4), exponent);
    const Double4 hi =
        whole_power(__builtin_convertvector(__builtin_shufflevector(c, c, 4, 5, 6, 7), Double4), exponent);
    const Float4 lo_f = __builtin_convertvector(lo, Float4), hi_f = __builtin_convertvector(hi, Float4);
    p = __builtin_shufflevector(lo_f, hi_f, 0, 1, 2, 3, 4, 5, 6, 7);
  } else {
    for (int j = 0; j < kPacketSize; ++j)
      if (raised[j]) p[j] = std::pow(r_dot_v[j], shininess);
  }
  p = raised ? p : splat8(0.0f);
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

RT_AVX2_CLONES
void add_lit(const PhongBatch& batch, Vec3 color, const float* scale, unsigned lanes, Vec3& sum) {
  const Float8 s = load8(scale);
  // The lanes read from the vectors themselves: copied to float arrays, GCC took each apart
  // through general registers (a quarter of the function's time).
  const Float8 r = (color.x * s) * load8(batch.r), g = (color.y * s) * load8(batch.g),
               b = (color.z * s) * load8(batch.b);
  for (unsigned m = lanes; m; m &= m - 1) {
    const int j = __builtin_ctz(m);
    sum.x += r[j];
    sum.y += g[j];
    sum.z += b[j];
  }
}

}  // namespace rt
