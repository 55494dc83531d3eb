// glTF's layered PBR extensions from files: every factor lands where io/gltf/materials.h says,
// files that require them load without a word, and the Khronos samples that use them import
// without "ignored" warnings.
#include <string>

#include <catch2/catch.hpp>

#include "io/gltf/loader.h"
#include "tests/support/gltf_import.h"
#include "tests/support/run_rtcli.h"
#include "tests/support/test_paths.h"

using namespace rt;

namespace {

ImportedModel import_clean(const std::string& path) {
  rt::test::ImportProblems problems;
  LimitUsage usage;
  auto model = rt::test::import_gltf(path, std::nullopt, LoadLimits{}, usage, problems);
  INFO(path << ": " << problems.message);
  REQUIRE(model);
  for (const std::string& w : problems.warnings) {
    INFO(w);
    CHECK(w.find("KHR_materials_") == std::string::npos);  // no extension of these ignored
  }
  return std::move(*model);
}

const Material& named(const ImportedModel& model, size_t index) {
  REQUIRE(index < model.materials.size());
  return model.materials[index];
}

}  // namespace

TEST_CASE("glTF layered extensions: each factor lands in the material", "[gltf][layers]") {
  const ImportedModel model = import_clean(rt::test::source_path("scenes/models/material_extensions.gltf"));
  REQUIRE(model.materials.size() == 6);
  const PbrLayers& coat = named(model, 0).pbr.layers;
  CHECK(coat.clearcoat.factor == 1.0f);
  CHECK(coat.clearcoat.roughness == 0.0f);
  CHECK(!coat.clearcoat.normal_map.map.present());
  const PbrLayers& sheen = named(model, 1).pbr.layers;
  CHECK(sheen.sheen.color == Vec3(0.9f, 0.55f, 1.0f));
  CHECK(sheen.sheen.roughness == Approx(0.35f));
  const Material& specular = named(model, 2);
  CHECK(specular.pbr.layers.specular.factor == 1.0f);
  CHECK(specular.pbr.layers.specular.color == Vec3(6.0f, 3.0f, 0.6f));  // above 1: F0 is clamped after the ior's
  CHECK(specular.ior == Approx(1.8f));
  const PbrLayers& aniso = named(model, 3).pbr.layers;
  CHECK(aniso.anisotropy.strength == Approx(0.9f));
  CHECK(aniso.anisotropy.rotation == 0.0f);
  const PbrLayers& film = named(model, 4).pbr.layers;
  CHECK(film.iridescence.factor == 1.0f);
  CHECK(film.iridescence.ior == Approx(1.33f));
  CHECK(film.iridescence.thickness_min == 100.0f);  // the default
  CHECK(film.iridescence.thickness_max == 420.0f);
  const Material& glass = named(model, 5);
  CHECK(glass.pbr.layers.dispersion == 8.0f);
  CHECK(glass.transmission == Vec3(1.0f));
  CHECK(glass.ior == Approx(1.6f));
}

TEST_CASE("glTF layered extensions: the Khronos samples import without ignoring them", "[gltf][layers]") {
  for (const char* sample :
       {"ClearcoatWicker/glTF/ClearcoatWicker.gltf", "IridescenceSuzanne/glTF-Binary/IridescenceSuzanne.glb",
        "AnisotropyRotationTest/glTF-Binary/AnisotropyRotationTest.glb"}) {
    const std::string path = rt::test::sample_model(sample);
    INFO(path);
    const ImportedModel model = import_clean(path);
    bool layered = false;
    for (const Material& m : model.materials) {
      const PbrLayers& l = m.pbr.layers;
      layered = layered || l.clearcoat.factor > 0.0f || l.iridescence.factor > 0.0f || l.anisotropy.strength > 0.0f;
    }
    CHECK(layered);
  }
}

TEST_CASE("cli: a file whose extensionsRequired names the six layered extensions renders, both integrators",
          "[cli][gltf][layers]") {
  const std::string out = rt::test::fresh_folder("material-extensions");
  const auto validated = rt::test::rtcli("validate scenes/material_extensions.json");
  CHECK(validated.code == 0);
  CHECK(validated.output.find("warning") == std::string::npos);
  for (const char* integrator : {"path", "whitted"}) {
    const auto rendered =
        rt::test::rtcli(std::string("render scenes/material_extensions.json --integrator ") + integrator +
                        " --width 48 --height 30 --spp 4 -q -o " + out + "/" + integrator + ".png");
    INFO(rendered.output);
    CHECK(rendered.code == 0);
  }
}
