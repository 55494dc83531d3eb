// The Khronos sample models (../shared/gltf) as rtcli imports and renders them: texture
// coordinates that land where the model's labels say, and a texture read from a file beside the
// model or from a GLB's own buffer. Skipped, with a warning, where the models are not there.
#include <algorithm>

#include <catch2/catch.hpp>

#include "core/render/renderer.h"
#include "tests/support/gltf_import.h"
#include "tests/support/loading.h"

using namespace rt;

TEST_CASE("glTF samples: TextureCoordinateTest's squares land where their labels say", "[gltf][materials][uv]") {
  if (!rt::test::have_sample_models()) {
    WARN("../shared/gltf not found: sample-model tests skipped");
    return;
  }
  Diagnostics diags;
  const auto loaded = load_scene(rt::test::sample_model("TextureCoordinateTest/glTF-Binary/TextureCoordinateTest.glb"),
                                 rt::test::load_options(), diags);
  REQUIRE(loaded);
  RenderSettings settings = loaded->settings;
  settings.width = settings.height = 64;
  Image image;
  render(loaded->scene, settings, image);
  // Each square's colour comes from its base colour texture through TEXCOORD_0: yellow top left,
  // orange top right, blue bottom left, green bottom right (the model's reference screenshot).
  const Vec3 yellow = image.at(13, 22), orange = image.at(50, 22), blue = image.at(16, 40), green = image.at(48, 40);
  INFO("yellow " << yellow.x << " " << yellow.y << " " << yellow.z);
  INFO("orange " << orange.x << " " << orange.y << " " << orange.z);
  INFO("blue " << blue.x << " " << blue.y << " " << blue.z);
  INFO("green " << green.x << " " << green.y << " " << green.z);
  CHECK(std::min(yellow.x, yellow.y) > 4.0f * yellow.z);
  CHECK(orange.x > 2.0f * orange.y);
  CHECK(orange.y > 2.0f * orange.z);
  CHECK(blue.z > 2.0f * std::max(blue.x, blue.y));
  CHECK(green.y > 2.0f * std::max(green.x, green.z));
}

TEST_CASE("glTF samples: BoxTextured's image from a file and from the GLB's buffer are the same texture",
          "[gltf][materials]") {
  if (!rt::test::have_sample_models()) {
    WARN("../shared/gltf not found: sample-model tests skipped");
    return;
  }
  const ImportedModel external = rt::test::imported(rt::test::sample_model("BoxTextured/glTF/BoxTextured.gltf"));
  const ImportedModel embedded = rt::test::imported(rt::test::sample_model("BoxTextured/glTF-Binary/BoxTextured.glb"));
  REQUIRE(external.materials.size() == 1);
  REQUIRE(embedded.materials.size() == 1);
  const TextureSlot& a = external.materials[0].texture;
  const TextureSlot& b = embedded.materials[0].texture;
  REQUIRE(a.present());
  REQUIRE(b.present());
  CHECK(a.mapping.filter == TextureFilter::kTrilinear);  // LINEAR_MIPMAP_LINEAR
  const Texture& ta = external.textures[a.texture];
  const Texture& tb = embedded.textures[b.texture];
  REQUIRE(ta.width() == tb.width());
  REQUIRE(ta.height() == tb.height());
  for (int y = 0; y < ta.height(); y += 17)
    for (int x = 0; x < ta.width(); x += 13) CHECK(ta.texel(x, y) == tb.texel(x, y));
  // The file was read beside the model; the GLB needed no other file.
  CHECK(std::any_of(external.files.begin(), external.files.end(),
                    [](const std::string& f) { return f.find("CesiumLogoFlat.png") != std::string::npos; }));
  CHECK(embedded.files.size() == 1);
}
