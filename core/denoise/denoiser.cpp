#include "core/denoise/denoiser.h"

#include "core/denoise/feature_filter.h"

namespace rt {
namespace {

constexpr NameEntry<DenoiserKind> kDenoiserEntries[] = {
    {"feature",
     {[]() -> std::unique_ptr<Denoiser> { return std::make_unique<FeatureFilter>(); }},
     "rtcli's own: an edge-avoiding a-trous filter on albedo-demodulated light, guided by normals, depth, "
     "albedo and each pixel's variance"}};
constexpr NameTable<DenoiserKind> kDenoisers{kDenoiserEntries};

}  // namespace

const NameTable<DenoiserKind>& denoisers() { return kDenoisers; }

std::unique_ptr<Denoiser> make_denoiser(std::string_view name) {
  const NameEntry<DenoiserKind>* e = kDenoisers.find(name);
  return e ? e->value.make() : nullptr;
}

}  // namespace rt
