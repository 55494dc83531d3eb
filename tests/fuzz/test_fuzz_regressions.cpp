// Replays every input in tests/fuzz/regressions/ through the fuzz targets' code: each once found
// a crash, a sanitizer report or a broken invariant. Runs in the plain suite (no clang needed) and
// under the sanitizers (tools/test.sh --sanitize).
#include <filesystem>

#include <catch2/catch.hpp>

#include "tests/fuzz/fuzz_targets.h"
#include "tests/support/test_paths.h"

namespace {

template <class Target>
int replay(const std::string& folder, const Target& target) {
  int count = 0;
  const std::string path = rt::test::source_path("tests/fuzz/regressions/" + folder);
  if (!std::filesystem::is_directory(path)) return 0;
  for (const auto& entry : std::filesystem::directory_iterator(path)) {
    if (!entry.is_regular_file()) continue;
    const std::string bytes = rt::test::read_file(entry.path().string());
    INFO(entry.path().string());
    CHECK(target(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()) == "");
    ++count;
  }
  return count;
}

}  // namespace

TEST_CASE("fuzz regressions: scene files", "[fuzz]") { CHECK(replay("scene", rt::fuzz::scene_json) >= 1); }
TEST_CASE("fuzz regressions: glTF models", "[fuzz]") { CHECK(replay("gltf", rt::fuzz::gltf_model) >= 5); }
TEST_CASE("fuzz regressions: BVH builds", "[fuzz]") { CHECK(replay("bvh", rt::fuzz::bvh_build) >= 1); }
TEST_CASE("fuzz regressions: EXR tiles", "[fuzz]") { CHECK(replay("exr", rt::fuzz::exr_tile) >= 1); }

TEST_CASE("fuzz regressions: environment images", "[fuzz]") {
  CHECK(replay("environment", rt::fuzz::environment_image) >= 1);
  CHECK(replay("environment_exr", rt::fuzz::environment_exr) >= 2);
  CHECK(replay("exr", rt::fuzz::environment_exr) >= 3);  // the tiles' finds, as environment files too
}
TEST_CASE("fuzz regressions: texture images", "[fuzz]") { CHECK(replay("texture", rt::fuzz::texture_image) >= 2); }

// Every seed image (one of each format stb_image knew, and the hostile ones) by every path an
// image takes into a scene.
TEST_CASE("fuzz regressions: image seeds by every path", "[fuzz]") {
  CHECK(replay("../../data/images", rt::fuzz::texture_image) >= 20);
  CHECK(replay("../../data/images", rt::fuzz::texture_file) >= 20);
  CHECK(replay("../../data/images", rt::fuzz::gltf_image) >= 20);
  CHECK(replay("../../data/images", rt::fuzz::extras_image) >= 20);
}
