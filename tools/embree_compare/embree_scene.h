// Embree 3 (Debian's libembree-dev, Apache-2.0) over the same triangles rtcli's BVH is built on,
// traced one ray at a time (rtcIntersect1 / rtcOccluded1) or in packets of eight (rtcIntersect8):
// the yardstick tools/embree_compare measures rtcli against.
#pragma once

#include <embree3/rtcore.h>

#include <vector>

#include "core/ray.h"
#include "core/shapes/triangle.h"

namespace rt {

// An Embree device limited to `threads` build threads (its thread pool starts with it: not part
// of a build's time).
class EmbreeDevice {
 public:
  explicit EmbreeDevice(unsigned threads);
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;
  RTCDevice get() const { return device_; }

 private:
  RTCDevice device_ = nullptr;
};

class EmbreeScene {
 public:
  // The triangles as one geometry, committed (built). Three vertices a triangle, as rtcli's
  // leaves copy them.
  EmbreeScene(const EmbreeDevice& device, const std::vector<PackedTriangle>& triangles);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // The closest hit's distance, or infinity.
  float intersect(const Ray& ray) const;
  bool occluded(const Ray& ray) const;
  // rays[first, first + 8) (fewer at the end) as one packet; returns how many hit.
  int intersect8(const std::vector<Ray>& rays, size_t first) const;

 private:
  RTCScene scene_ = nullptr;
};

}  // namespace rt
