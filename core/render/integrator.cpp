#include "core/render/integrator.h"

#include "core/render/debug_integrators.h"
#include "core/render/path_integrator.h"
#include "core/render/whitted_integrator.h"

namespace rt {
namespace {

struct Entry {
  const char* name;
  std::unique_ptr<Integrator> (*make)();
  bool radiance;  // false: a debug view (integrator_shows_radiance)
  bool samples_pixels = false;  // integrator_samples_pixels
};

template <class T>
std::unique_ptr<Integrator> make() {
  return std::make_unique<T>();
}

// The name table. Adding an integrator = one file and one line here.
constexpr Entry kIntegrators[] = {
    {"whitted", &make<WhittedIntegrator>, true},
    {"path", &make<PathIntegrator>, true, true},
    {"normals", &make<NormalsIntegrator>, false},
    {"uv", &make<UvIntegrator>, false},
    {"depth", &make<DepthIntegrator>, false},
    {"albedo", &make<AlbedoIntegrator>, false},
};

}  // namespace

std::unique_ptr<Integrator> make_integrator(std::string_view name) {
  for (const Entry& e : kIntegrators)
    if (name == e.name) return e.make();
  return nullptr;
}

bool integrator_shows_radiance(std::string_view name) {
  for (const Entry& e : kIntegrators)
    if (name == e.name) return e.radiance;
  return true;
}

bool integrator_samples_pixels(std::string_view name) {
  for (const Entry& e : kIntegrators)
    if (name == e.name) return e.samples_pixels;
  return false;
}

std::vector<std::string> integrator_names() {
  std::vector<std::string> names;
  for (const Entry& e : kIntegrators) names.emplace_back(e.name);
  return names;
}

}  // namespace rt
