// One name table per closed set of choices (core/name_table.h): parse, name, list, help.
#include <catch2/catch.hpp>

#include "core/accel/isa.h"
#include "core/render/integrator.h"
#include "core/render_settings.h"
#include "core/stereo.h"

using namespace rt;

TEST_CASE("name tables: every name parses to its value and back", "[names]") {
  CHECK(kToneMaps.parse("filmic") == ToneMap::kFilmic);
  CHECK_FALSE(kToneMaps.parse("Filmic"));
  CHECK(kToneMaps.name(ToneMap::kClamp) == "clamp");
  CHECK(kToneMaps.list() == "clamp, filmic");
  CHECK(kToneMaps.help() == "clamp: values above 1 cut to white; filmic: highlights rolled off (ACES fit)");
  CHECK(kSecondaryShadows.parse("scaled") == true);
  CHECK(kSecondaryShadows.name(false) == "full");
  CHECK(kStereoModes.size() == 5);
  for (const auto& e : kStereoModes.entries()) CHECK(kStereoModes.parse(e.name) == e.value);
  for (const auto& e : kTextureFilters.entries()) CHECK(kTextureFilters.name(e.value) == e.name);
  for (const auto& e : kIsas.entries()) CHECK(parse_isa(isa_name(e.value)) == e.value);
  CHECK(kSamplePositions.names() == std::vector<std::string>{"corners", "centres"});
  // A registry's table: the integrators, each making its integrator.
  REQUIRE(integrators().find("path"));
  CHECK(integrators().find("path")->value.samples_pixels);
  CHECK_FALSE(integrators().find("normals")->value.shows_radiance);
  for (const auto& e : integrators().entries()) CHECK(make_integrator(e.name) != nullptr);
  CHECK(make_integrator("aov-normal") == nullptr);  // the EXR layers come from the colour's pass now
}
