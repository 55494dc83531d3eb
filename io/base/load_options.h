// What the caller tells the loaders: threads for the BVH build, the names the render pipeline
// offers (io does not link the renderer; cli passes integrators().names()
// and pixel_samplers().names()), and the limits on what
// a file may ask for. The limits keep a hostile or broken file from exhausting memory or time:
// everything is checked against them before it is allocated. docs/errors-and-limits.md ("Limits") documents
// the defaults; the fuzzers run with smaller ones.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/accel/isa.h"

namespace rt {

class LoadCache;  // io/assemble/load_cache.h

struct LoadLimits {
  uint64_t scene_file_bytes = uint64_t{64} << 20;  // a JSON scene file
  uint64_t gltf_json_bytes = uint64_t{64} << 20;   // a .gltf file, or the JSON chunk of a .glb
  uint64_t gltf_total_bytes = uint64_t{1} << 30;   // a model's files together: .glb or .gltf plus its .bin files
  uint64_t vertices = uint64_t{1} << 25;           // in a scene's meshes, each stored mesh once (33,554,432)
  uint64_t triangles = uint64_t{1} << 25;          // in a scene's meshes, each stored mesh once
  uint64_t instances = uint64_t{1} << 20;          // analytic shapes plus placed mesh primitives
  uint64_t nodes = uint64_t{1} << 20;              // scene-file nodes, and glTF nodes per file
  uint64_t texture_texels = uint64_t{1} << 25;     // in one texture image (e.g. 8192 x 4096)
  uint64_t scene_texels = uint64_t{1} << 27;       // in all of a scene's textures together, mip levels included
  uint64_t animation_keys = uint64_t{1} << 20;     // in all of a scene's tracks, after splitting wide rotations
  // A glTF file's image and buffer URIs may leave its folder (`--allow-outside-files`). A scene
  // file's own paths are never restricted: the user wrote them.
  bool outside_files = false;
  // Not a limit but a share of the machine: how many threads decode a glTF file's images
  // (0: one per CPU the process may use; rtcli passes --threads).
  unsigned decode_threads = 0;
};

// What a scene has taken of its limits so far, counted as it loads: a model, an image or a track
// is checked against what is left before it is read, decoded or expanded.
struct LimitUsage {
  uint64_t texels = 0;  // mip levels included
  uint64_t vertices = 0;
  uint64_t triangles = 0;
  uint64_t animation_keys = 0;  // a glTF sampler shared by several channels counts once
};

struct LoadOptions {
  unsigned threads = 0;                             // for the BVH build; 0 = one per usable CPU
  Isa isa = best_isa();                             // the BVH kernels the scene's BVHs use
  std::vector<std::string> integrators{"whitted"};  // valid values of /render/integrator
  std::vector<std::string> pixel_samplers{"none"};  // valid values of /render/antialias/mode
  LoadLimits limits;
  bool build_bvh = true;  // false: check everything, build no acceleration structure (validate)
  // A glTF camera to look through, by the camera's name (or its node's): `rtcli render --camera`.
  std::optional<std::string> camera;
  // The frame whose Scene the loader builds (LoadedScene::scene): the first a render will show.
  // Default: the timeline's first frame.
  std::optional<int> frame;
  // A model on its own: which of its animations plays (--animation; default: all), and the
  // frame rate its timeline is sampled at (--fps; default kModelFps, Blender's).
  std::optional<std::string> animation;
  std::optional<float> fps;
  // The scene's integrator replaced (--integrator): what BLEND's coverage and the warnings follow.
  std::optional<std::string> integrator;
  // The scene's background and ambient colours replaced (--background, --ambient), linear RGB.
  std::optional<std::array<float, 3>> background, ambient;
  // An environment image around the scene, replacing its background (--environment): a glTF
  // model lit by an HDR image without a scene file.
  struct EnvironmentChoice {
    std::string path;
    float intensity = 1.0f;
    float rotate = 0.0f;  // degrees about +Y
  };
  std::optional<EnvironmentChoice> environment;
  // What earlier loads of the scene read and still hold, while their files are unchanged
  // (rtcli watch); null: read everything.
  LoadCache* cache = nullptr;
};

// A model on its own: its frame rate without --fps, and its world (Blender's default world
// colour, which lights nothing in Whitted tracing). No ambient light, as in Blender.
inline constexpr float kModelFps = 24.0f;
inline constexpr float kModelBackground = 0.0509f;

}  // namespace rt
