#include "core/render/integrator.h"

#include "core/render/debug_integrators.h"
#include "core/render/path_integrator.h"
#include "core/render/whitted_integrator.h"

namespace rt {
namespace {

template <class T>
std::unique_ptr<Integrator> make() {
  return std::make_unique<T>();
}

// The name table. Adding an integrator = one file and one line here.
constexpr NameEntry<IntegratorKind> kIntegratorEntries[] = {
    {"whitted", {&make<WhittedIntegrator>, true, false}, "Whitted ray tracing with the proposal's extras (default)"},
    {"path", {&make<PathIntegrator>, true, true}, "path tracing"},
    {"normals", {&make<NormalsIntegrator>, false, false}, "debug view: shading normals"},
    {"uv", {&make<UvIntegrator>, false, false}, "debug view: texture coordinates"},
    {"depth", {&make<DepthIntegrator>, false, false}, "debug view: distance, white near"},
    {"albedo", {&make<AlbedoIntegrator>, false, false}, "debug view: the diffuse colour"},
};
constexpr NameTable<IntegratorKind> kIntegrators{kIntegratorEntries};

}  // namespace

const NameTable<IntegratorKind>& integrators() { return kIntegrators; }

std::unique_ptr<Integrator> make_integrator(std::string_view name) {
  const NameEntry<IntegratorKind>* e = kIntegrators.find(name);
  return e ? e->value.make() : nullptr;
}

bool integrator_shows_radiance(std::string_view name) {
  const NameEntry<IntegratorKind>* e = kIntegrators.find(name);
  return !e || e->value.shows_radiance;
}

bool integrator_samples_pixels(std::string_view name) {
  const NameEntry<IntegratorKind>* e = kIntegrators.find(name);
  return e && e->value.samples_pixels;
}

}  // namespace rt
