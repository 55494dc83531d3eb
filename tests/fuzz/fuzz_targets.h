// What each fuzzer does with one input, as plain functions: the libFuzzer entry points
// (tests/fuzz/fuzz_*.cpp, built with clang by tools/fuzz.sh) call them, and so does the normal
// test suite, which replays every input in tests/fuzz/regressions/ without needing clang.
// Each returns an empty string, or what invariant the input broke (a loader must never crash,
// hang or exhaust memory; a BVH must stay sound). Rejecting an input is not a failure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace rt {
class Environment;
}

namespace rt::fuzz {

// A JSON scene file: parse, check, build (glTF references resolve against scenes/), render 4x4.
std::string scene_json(const uint8_t* data, size_t size);
// A glTF model, .gltf text or .glb bytes: import, place every instance, build a BVH, check it.
std::string gltf_model(const uint8_t* data, size_t size);
// Triangles with arbitrary float coordinates (raw bits: extremes, denormals; non-finite ones
// dropped): build a BVH, check its structure and trace rays against brute force.
std::string bvh_build(const uint8_t* data, size_t size);

// Image bytes of any format: decode as colour, data and alpha (PNG and JPEG decode, the rest is
// refused by name), then sample with every filter and wrap mode at extreme coordinates; every
// value must be finite.
std::string texture_image(const uint8_t* data, size_t size);
// The same bytes by each path an image takes into a scene: a scene file's texture file (loaded,
// then a 4x4 render), a glTF image in a buffer view (as colour, metallic-roughness, normal map,
// emission and alpha mask), and the image file a glTF material's rtcli_bump extras name.
std::string texture_file(const uint8_t* data, size_t size);
std::string gltf_image(const uint8_t* data, size_t size);
// Environment image bytes (Radiance .hdr): decoded with a texel limit, made into an environment,
// whose sampling must give finite directions with the density pdf() gives them, and finite
// radiance everywhere.
std::string environment_image(const uint8_t* data, size_t size);
// The same for OpenEXR bytes as a scene's environment file: loaded as a scene loads it (the
// bounded reader, the structure walk, OpenEXR's RGBA interface, the texel budget), then sampled.
std::string environment_exr(const uint8_t* data, size_t size);
// The sampling checks of an environment (`seed` picks the sample points).
std::string check_environment_sampling(const Environment& env, uint64_t seed);

// OpenEXR bytes as a tile given to rtcli merge: read (every channel, the string attributes) within a
// pixel limit of 2^20, so 12 x 2^20 values (where merge's own allows 2^26 pixels: a product the
// fuzzer's memory limit would stop first), checked, and merged alone (which succeeds only for a
// whole image).
std::string exr_tile(const uint8_t* data, size_t size);
std::string extras_image(const uint8_t* data, size_t size);

// The input written to a file of this process's own (for loaders that read files).
void write_bytes(const std::filesystem::path& path, const uint8_t* data, size_t size);

// For the libFuzzer entry points: a broken invariant aborts, which libFuzzer reports and saves.
int abort_on_problem(const std::string& problem);

}  // namespace rt::fuzz
