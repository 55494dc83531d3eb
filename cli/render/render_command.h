// `rtcli render SCENE [-o OUT] [--threads N] [--isa sse|avx2|avx512|auto] [--width W] [--height H]
//   [--seed S] [--integrator NAME] [--glossy-samples N] [--no-glossy] [--no-textures] [--no-bumps]
//   [--texture-filter NAME] [--shadow-samples N] [--secondary-shadows scaled|full] [--preview]
//   [--exposure STOPS] [--tone-map clamp|filmic] [--spp N] [--noise-threshold T] [--clamp C]
//   [--samples-debug] [--aa MODE] [--aa-samples N] [--aa-threshold T] [--aa-depth D]
//   [--aa-positions corners|centres] [--aa-debug] [--frame N | --frames LIST] [--camera NAME]
//   [--animation NAME|INDEX] [--fps F] [--background R,G,B] [--ambient R,G,B]
//   [--environment FILE [--environment-intensity K] [--environment-rotate DEG]] [--stereo MODE]
//   [--dither] [--allow-outside-files] [--stats FILE.json] [--crop x0,y0,x1,y1 | --tile I/N|auto]
//   [--chunk I/N|auto] [--skip-existing] [--exr-float] [--aov albedo,normal,depth] [--denoise] [--quiet]
//   [--progress auto|bar|lines|none] [--max-depth N]`
// (cli/main.cpp declares them, with their help). RenderCommand holds the options as given; the
// command reads them once into a checked RenderJob (cli/render/render_job.h) and the scene's
// settings with their overrides, and nothing below it sees this struct.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace rt {

struct RenderCommand {
  std::string scene;
  std::string output;  // empty: <scene name>.png (.gif for a frame range) in the current folder
  std::optional<unsigned> threads;
  std::optional<std::string> isa;  // --isa: sse, avx2, avx512 or auto (cli/common/isa_choice.h)
  std::optional<int> width, height;
  std::optional<uint64_t> seed;
  std::optional<std::string> integrator;
  std::optional<int> glossy_samples;
  std::optional<int> shadow_samples;
  std::optional<std::string> secondary_shadows;  // "full" or "scaled"
  std::optional<std::string> sampler;            // kSampleSequences
  std::optional<float> exposure;                 // stops
  std::optional<std::string> tone_map;           // "clamp" or "filmic"
  std::optional<std::string> view_transform;     // an OpenColorIO view ("Filmic", "AgX", "Standard")
  std::optional<std::string> look;               // and its look ("Medium High Contrast")
  std::optional<std::string> ocio_config;        // the config (default: Blender's, where installed)
  std::optional<int> spp;                        // the path tracer's samples per pixel
  std::optional<float> noise_threshold;          // its adaptive stop (0: off)
  std::optional<double> time;                    // --time: seconds a frame may take (path tracer's passes)
  std::optional<float> clamp;                    // its largest sample value (0: off)
  bool samples_debug = false;                    // also write <output>.samples.png
  bool preview = false;                          // the draft preset (preview_settings)
  std::optional<std::string> aa_mode;
  std::optional<int> aa_samples;
  std::optional<float> aa_threshold;
  std::optional<int> aa_depth;
  std::optional<std::string> aa_positions;
  bool aa_debug = false;  // also write <output>.aa-refined.png and <output>.aa-depth.png
  bool no_glossy = false;
  bool no_textures = false;
  bool no_bumps = false;
  std::optional<std::string> texture_filter;
  std::optional<std::string> frames;               // "A-B", "A-BxS", "1,5,9-12" (--frames), or "N" (--frame)
  std::optional<std::string> camera;               // a glTF camera by name
  std::optional<std::string> animation;            // a model on its own: one of its animations, by name or index
  std::optional<float> fps;                        // a model on its own: its timeline's frame rate (default 24)
  std::optional<std::string> background, ambient;  // "R,G,B" or one number: replace the scene's
  std::optional<std::string> environment;          // an HDR or EXR image around the scene (replaces its background)
  std::optional<float> environment_intensity, environment_rotate;
  std::optional<std::string> stereo;  // none, anaglyph, side_by_side, top_bottom, pair: replaces the camera's
  bool dither = false;                // GIF frames: Floyd-Steinberg error diffusion
  bool allow_outside_files = false;   // glTF files may read images and buffers outside their folder
  std::string stats;  // --stats FILE: the render's figures as JSON (cli/render/render_stats.h); empty: none
  // Part of the render (cli/frames/render_share.h): a window of the image, a band of rows, a share of the frames.
  std::optional<std::string> crop, tile, chunk;
  bool skip_existing = false;           // frames whose output is there and complete are not rendered again
  bool exr_float = false;               // EXR output: 32-bit floats (default half)
  std::optional<std::string> aov;       // EXR output: layers beside the colour, any of albedo,normal,depth,variance
  bool denoise = false;                 // --denoise: the image denoised (an EXR keeps the raw one as layer "raw")
  std::optional<std::string> denoiser;  // --denoiser NAME (implies --denoise)
  std::optional<std::string> resume;    // --resume FILE.exr: add samples to that render (cli/render/resume_plan.h)
  bool quiet = false;
  std::optional<std::string> progress;  // --progress auto|bar|lines|none (cli/common/progress_bar.h)
  std::optional<int> max_depth;         // --max-depth: bounces after the camera ray
};

int run_render(const RenderCommand& cmd);

}  // namespace rt
