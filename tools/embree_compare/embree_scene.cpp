#include "tools/embree_compare/embree_scene.h"

#include <stdexcept>
#include <string>

namespace rt {

EmbreeDevice::EmbreeDevice(unsigned threads) {
  device_ = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
  if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed");
}

EmbreeDevice::~EmbreeDevice() { rtcReleaseDevice(device_); }

EmbreeScene::EmbreeScene(const EmbreeDevice& device, const std::vector<PackedTriangle>& triangles) {
  scene_ = rtcNewScene(device.get());
  RTCGeometry geometry = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
  const size_t n = triangles.size();
  auto* v = static_cast<float*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
  auto* index = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
  for (size_t i = 0; i < n; ++i) {
    const PackedTriangle& t = triangles[i];
    const Vec3 corners[3] = {t.v0, t.v0 + t.e1, t.v0 + t.e2};
    for (int c = 0; c < 3; ++c) {
      for (int a = 0; a < 3; ++a) v[(3 * i + static_cast<size_t>(c)) * 3 + static_cast<size_t>(a)] = corners[c][a];
      index[3 * i + static_cast<size_t>(c)] = static_cast<unsigned>(3 * i + static_cast<size_t>(c));
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
}

EmbreeScene::~EmbreeScene() { rtcReleaseScene(scene_); }

namespace {

RTCRay to_embree(const Ray& r) {
  RTCRay e;
  e.org_x = r.origin.x;
  e.org_y = r.origin.y;
  e.org_z = r.origin.z;
  e.tnear = r.tmin;
  e.dir_x = r.direction.x;
  e.dir_y = r.direction.y;
  e.dir_z = r.direction.z;
  e.time = 0.0f;
  e.tfar = r.tmax;
  e.mask = ~0u;
  e.id = 0;
  e.flags = 0;
  return e;
}

}  // namespace

float EmbreeScene::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = to_embree(ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInfinity : rh.ray.tfar;
}

bool EmbreeScene::occluded(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_embree(ray);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar < 0.0f;  // Embree marks a blocked ray with tfar = -inf
}

int EmbreeScene::intersect8(const std::vector<Ray>& rays, size_t first) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(32) int valid[8];
  alignas(32) RTCRayHit8 rh;
  for (int k = 0; k < 8; ++k) {
    const size_t i = first + static_cast<size_t>(k);
    valid[k] = i < rays.size() ? -1 : 0;
    const RTCRay e = to_embree(rays[i < rays.size() ? i : first]);
    rh.ray.org_x[k] = e.org_x;
    rh.ray.org_y[k] = e.org_y;
    rh.ray.org_z[k] = e.org_z;
    rh.ray.tnear[k] = e.tnear;
    rh.ray.dir_x[k] = e.dir_x;
    rh.ray.dir_y[k] = e.dir_y;
    rh.ray.dir_z[k] = e.dir_z;
    rh.ray.time[k] = 0.0f;
    rh.ray.tfar[k] = e.tfar;
    rh.ray.mask[k] = ~0u;
    rh.ray.id[k] = 0;
    rh.ray.flags[k] = 0;
    rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
  }
  rtcIntersect8(valid, scene_, &context, &rh);
  int hits = 0;
  for (int k = 0; k < 8; ++k) hits += valid[k] && rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
  return hits;
}

}  // namespace rt
