#include "cli/bench/generated_mesh.h"

#include <cmath>

namespace rt {

TriangleMesh make_benchmark_mesh(size_t min_triangles) {
  // rings x segments quads, two triangles each, minus the degenerate ones at the poles.
  const auto rings = static_cast<size_t>(std::ceil(std::sqrt(static_cast<double>(min_triangles) / 4.0))) + 1;
  const size_t segments = 2 * rings;
  TriangleMesh mesh;
  for (size_t i = 0; i <= rings; ++i) {
    const float theta = kPi * static_cast<float>(i) / static_cast<float>(rings);
    for (size_t j = 0; j <= segments; ++j) {
      const float phi = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(segments);
      const Vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      // Smooth periodic bumps at three scales: big lobes, ridges, fine grit.
      const float r = 1.0f + 0.25f * std::sin(3.0f * phi) * std::sin(2.0f * theta) +
                      0.08f * std::sin(17.0f * phi + 5.0f * theta) * std::cos(13.0f * theta) +
                      0.02f * std::sin(91.0f * phi) * std::sin(83.0f * theta);
      mesh.positions.push_back(r * dir);
    }
  }
  const auto vertex = [&](size_t i, size_t j) { return static_cast<uint32_t>(i * (segments + 1) + j); };
  for (size_t i = 0; i < rings; ++i) {
    for (size_t j = 0; j < segments; ++j) {
      if (i != 0) mesh.indices.insert(mesh.indices.end(), {vertex(i, j), vertex(i, j + 1), vertex(i + 1, j)});
      if (i + 1 != rings)
        mesh.indices.insert(mesh.indices.end(), {vertex(i, j + 1), vertex(i + 1, j + 1), vertex(i + 1, j)});
    }
  }
  return mesh;
}

}  // namespace rt
