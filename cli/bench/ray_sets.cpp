#include "cli/bench/ray_sets.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/accel/bvh.h"
#include "core/camera.h"
#include "core/parallel_for.h"
#include "core/rng.h"
#include "core/thread_count.h"
#include "io/base/atomic_file.h"

namespace rt {
namespace {

constexpr char kMagic[8] = {'R', 'T', 'R', 'A', 'Y', 'S', '0', '1'};
constexpr uint64_t kMaxRaysPerSet = 1ull << 28;  // 8 GiB of rays: anything larger is not a ray file

bool inside(const Aabb& box, Vec3 p) {
  return p.x >= box.lo.x && p.x <= box.hi.x && p.y >= box.lo.y && p.y <= box.hi.y && p.z >= box.lo.z && p.z <= box.hi.z;
}

Vec3 point_in(const Aabb& box, Rng& rng) {
  return box.lo + box.extent() * Vec3(rng.next_float(), rng.next_float(), rng.next_float());
}

std::vector<Ray> incoherent_rays(const Aabb& bounds) {
  const Vec3 centre = bounds.centre();
  const float side = 3.0f * max_component(bounds.extent());
  const Aabb cube{centre - Vec3(0.5f * side),
                  centre + Vec3(0.5f * side)};  // braces: clang 14 has no C++20 parenthesized aggregates
  std::vector<Ray> rays(kIncoherentRays);
  for (size_t i = 0; i < rays.size(); ++i) {
    Rng rng(mix64(i), 7);
    Vec3 origin = point_in(cube, rng);
    while (inside(bounds, origin)) origin = point_in(cube, rng);  // outside the model's box
    rays[i].origin = origin;
    rays[i].direction = glm::normalize(point_in(bounds, rng) - origin);
  }
  return rays;
}

}  // namespace

std::vector<RaySet> make_ray_sets(const PrimitiveSet& prims) {
  const unsigned threads = resolve_thread_count(0);
  const Bvh bvh(prims, BvhBuildOptions{threads});
  const Aabb bounds = bvh.bounds();
  const Camera camera = Camera::framing(bounds, 40.0f, static_cast<float>(kPrimaryWidth) / kPrimaryHeight);
  RaySet primary{"primary", false, std::vector<Ray>(static_cast<size_t>(kPrimaryWidth) * kPrimaryHeight)};
  for (size_t i = 0; i < primary.rays.size(); ++i)
    primary.rays[i] = camera.generate_ray(static_cast<float>(i % kPrimaryWidth) + 0.5f,
                                          static_cast<float>(i / kPrimaryWidth) + 0.5f, kPrimaryWidth, kPrimaryHeight);

  // Occlusion rays start where the primary rays hit, off the surface as the renderer starts them.
  std::vector<Ray> shadow(primary.rays.size());
  std::vector<uint8_t> has(primary.rays.size(), 0);
  const Vec3 light = bounds.centre() + glm::length(bounds.extent()) * Vec3(0.4f, 1.0f, 0.6f);
  parallel_for(primary.rays.size(), threads, 4096, [&](unsigned, size_t i) {
    Ray ray = primary.rays[i];
    Hit hit;
    if (!bvh.intersect(ray, hit)) return;
    Vec3 p = ray.at(hit.t), n = -ray.direction;
    // Far from the surface by t's rounding at most (a generous bound); a triangle's point is
    // found from its barycentrics instead, as the renderer does, with pbrt-v4's bound.
    Vec3 error = float_gamma(16) * (glm::abs(ray.origin) + glm::abs(hit.t * ray.direction));
    if (prims.kind(hit.prim) == PrimitiveKind::kTriangle) {
      const PackedTriangle& tri = prims.triangles[hit.prim];
      p = tri.v0 + hit.b1 * tri.e1 + hit.b2 * tri.e2;
      error = float_gamma(7) * (glm::abs(tri.v0) + glm::abs(hit.b1 * tri.e1) + glm::abs(hit.b2 * tri.e2));
      n = glm::normalize(glm::cross(tri.e1, tri.e2));
    }
    const Vec3 to_light = light - p;
    shadow[i].direction = glm::normalize(to_light);
    shadow[i].origin = offset_ray_origin(p, error, n, shadow[i].direction);
    shadow[i].tmax = glm::length(to_light);
    has[i] = 1;
  });
  RaySet occlusion{"occlusion", true, {}};
  for (size_t i = 0; i < shadow.size(); ++i)
    if (has[i]) occlusion.rays.push_back(shadow[i]);
  return {std::move(primary), RaySet{"incoherent", false, incoherent_rays(bounds)}, std::move(occlusion)};
}

bool write_ray_sets(const std::string& path, const std::vector<RaySet>& sets, std::string& error) {
  std::vector<uint8_t> bytes;
  const auto put = [&](const void* p, size_t n) {
    const size_t at = bytes.size();
    bytes.resize(at + n);
    std::memcpy(bytes.data() + at, p, n);
  };
  put(kMagic, sizeof kMagic);
  const auto count = static_cast<uint32_t>(sets.size());
  put(&count, sizeof count);
  for (const RaySet& set : sets) {
    const auto length = static_cast<uint8_t>(std::min<size_t>(set.name.size(), 255));
    put(&length, 1);
    put(set.name.data(), length);
    const uint8_t kind = set.occlusion ? 1 : 0;
    put(&kind, 1);
    const uint64_t n = set.rays.size();
    put(&n, sizeof n);
    for (const Ray& r : set.rays) {
      const float f[8] = {r.origin.x,    r.origin.y,    r.origin.z,    r.tmin,
                          r.direction.x, r.direction.y, r.direction.z, r.tmax};
      put(f, sizeof f);
    }
  }
  return write_file_atomically(path, bytes, error);
}

bool read_ray_sets(const std::string& path, std::vector<RaySet>& sets, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot open " + path;
    return false;
  }
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  size_t at = 0;
  const auto take = [&](void* p, size_t n) {
    if (bytes.size() - at < n) return false;
    std::memcpy(p, bytes.data() + at, n);
    at += n;
    return true;
  };
  char magic[8] = {};
  uint32_t count = 0;
  if (!take(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof magic) != 0 || !take(&count, sizeof count)) {
    error = path + " is not a ray file (it should start with RTRAYS01; `rtcli bench --save-rays` writes one)";
    return false;
  }
  sets.clear();
  for (uint32_t s = 0; s < count; ++s) {
    RaySet set;
    uint8_t length = 0, kind = 0;
    uint64_t n = 0;
    bool ok = take(&length, 1);
    if (ok) {
      set.name.resize(length);
      ok = take(set.name.data(), length) && take(&kind, 1) && take(&n, sizeof n) && kind <= 1 && n <= kMaxRaysPerSet &&
           (bytes.size() - at) / 32 >= n;
    }
    if (!ok) {
      error = path + ": ray set " + std::to_string(s + 1) + " of " + std::to_string(count) +
              " is cut short or malformed (at byte " + std::to_string(at) + ")";
      return false;
    }
    set.occlusion = kind == 1;
    set.rays.resize(n);
    for (Ray& r : set.rays) {
      float f[8] = {};
      take(f, sizeof f);
      r.origin = Vec3(f[0], f[1], f[2]);
      r.tmin = f[3];
      r.direction = Vec3(f[4], f[5], f[6]);
      r.tmax = f[7];
      if (!std::isfinite(r.origin.x + r.origin.y + r.origin.z + r.direction.x + r.direction.y + r.direction.z) ||
          std::isnan(r.tmin) || std::isnan(r.tmax) || r.direction == Vec3(0.0f)) {
        error = path + ": ray set '" + set.name + "' holds a ray with a non-finite or zero component";
        return false;
      }
    }
    sets.push_back(std::move(set));
  }
  if (at != bytes.size()) {
    error = path + ": " + std::to_string(bytes.size() - at) + " bytes follow the last ray set";
    return false;
  }
  return true;
}

}  // namespace rt
