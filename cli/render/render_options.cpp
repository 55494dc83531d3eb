#include "cli/render/render_options.h"

#include "cli/common/number_checks.h"
#include "cli/common/progress_bar.h"
#include "core/accel/isa.h"
#include "core/denoise/denoiser.h"
#include "core/render/integrator.h"
#include "core/render/pixel_sampler.h"
#include "core/render_settings.h"
#include "core/stereo.h"
#include "io/image/gif_file.h"

namespace rt {

const char* const kOutsideFilesHelp =
    "Let glTF files read images and buffers outside their own folder (by default a model's URIs must stay in "
    "it, so that a downloaded model cannot show other files)";

std::string isa_help() {
  return "Instruction set of the BVH traversal: " + kIsas.help() +
         "; auto: the best this CPU runs (default: RTCLI_ISA, else auto); the image is the same "
         "with any";
}

void add_scene_options(CLI::App& cmd, RenderCommand& r) {
  cmd.add_option("--threads", r.threads, "Worker threads (default: one per CPU this process may use)")
      ->check(whole_number(1, 1024));
  cmd.add_option("--width", r.width, "Image width in pixels (overrides the scene)")
      ->check(whole_number(1, kMaxImageSide));
  cmd.add_option("--height", r.height, "Image height in pixels (overrides the scene)")
      ->check(whole_number(1, kMaxImageSide));
  cmd.add_option("--seed", r.seed, "Seed of every random stream (overrides the scene)")
      ->check(whole_number(0, UINT64_MAX));
  cmd.add_option("--integrator", r.integrator, integrators().help() + " (overrides the scene)");
  cmd.add_option("--glossy-samples", r.glossy_samples, "Rays per glossy reflection (overrides the scene)")
      ->check(whole_number(1, kMaxGlossySamples));
  cmd.add_flag("--no-glossy", r.no_glossy, "Render glossy surfaces as perfect mirrors");
  cmd.add_flag("--no-textures", r.no_textures, "Ignore colour and specular textures (kd and ks alone)");
  cmd.add_flag("--no-bumps", r.no_bumps, "Ignore bump and normal maps");
  cmd.add_option("--texture-filter", r.texture_filter,
                 "Every texture filtered so: " + kTextureFilters.help() + " (overrides the scene)");
  cmd.add_option("--shadow-samples", r.shadow_samples,
                 "Shadow rays per area light and shading point (overrides the scene)")
      ->check(whole_number(1, kMaxShadowSamples));
  cmd.add_flag("--preview", r.preview,
               "Draft: no anti-aliasing, a quarter of the shadow and glossy samples (at most 4); options "
               "given beside it still apply");
  cmd.add_option("--sampler", r.sampler, "Where samples fall: " + kSampleSequences.help() + " (overrides the scene)");
  cmd.add_option("--secondary-shadows", r.secondary_shadows, kSecondaryShadows.help() + " (overrides the scene)");
  cmd.add_option("--exposure", r.exposure,
                 "Exposure in stops: the radiance is multiplied by 2^STOPS before the tone curve (overrides the "
                 "scene)")
      ->check(real_number(-kMaxExposure, kMaxExposure));
  cmd.add_option("--max-depth", r.max_depth,
                 "Bounces after the camera ray: reflections and refractions (Whitted), any bounce (path tracer) "
                 "(overrides the scene's render.max_depth)")
      ->check(whole_number(0, kMaxRecursionDepth));
  cmd.add_option("--spp", r.spp, "Path tracer: the most samples per pixel (overrides the scene's r.samples_per_pixel)")
      ->check(whole_number(1, kMaxSamplesPerPixel));
  cmd.add_option("--noise-threshold", r.noise_threshold,
                 "Path tracer: a pixel stops sampling once its relative error is below T (0: off; overrides "
                 "the scene)")
      ->check(real_number(0.0, 1.0));
  cmd.add_option("--clamp", r.clamp,
                 "Path tracer: the largest value one sample may add, against fireflies (0: off; biased; "
                 "overrides the scene)")
      ->check(real_number(0.0, 1e30));
  cmd.add_option("--tone-map", r.tone_map, kToneMaps.help() + " (overrides the scene)");
  cmd.add_option("--aa", r.aa_mode, "Anti-aliasing: " + pixel_samplers().help() + " (overrides the scene)");
  cmd.add_option("--aa-samples", r.aa_samples, "Uniform anti-aliasing: N x N rays per pixel")
      ->check(whole_number(1, kMaxSamplesPerAxis));
  cmd.add_option("--aa-threshold", r.aa_threshold,
                 "Adaptive anti-aliasing: split a cell whose samples differ by more than T (0-1, displayed values)")
      ->check(real_number(0.0, 1.0));
  cmd.add_option("--aa-depth", r.aa_depth, "Adaptive anti-aliasing: most splits of a pixel")
      ->check(whole_number(0, kMaxAdaptiveDepth));
  cmd.add_option("--aa-positions", r.aa_positions,
                 "Adaptive anti-aliasing, where the samples go: " + kSamplePositions.help());
  cmd.add_option("--camera", r.camera,
                 "Look through a glTF camera, by its name or its node's (default: the scene's camera, or a "
                 "glTF file's first)");
  cmd.add_option("--animation", r.animation,
                 "A glTF file on its own: play one of its animations, by name or index (default: all of them)");
  cmd.add_option("--fps", r.fps, "A glTF file on its own: frames per second of its animation (default 24)")
      ->check(real_number(kMinGifFps, 1000.0));
  cmd.add_option("--background", r.background,
                 "Background colour, linear R,G,B or one number (overrides the scene; a glTF file's is 0.0509)")
      ->check(color_value());
  cmd.add_option("--ambient", r.ambient,
                 "Ambient light, linear R,G,B or one number (overrides the scene; a glTF file has none)")
      ->check(color_value());
  cmd.add_option("--environment", r.environment,
                 "An equirectangular Radiance .hdr or OpenEXR .exr image around the scene, lighting it (path "
                 "tracer) and seen behind it: replaces the scene's background (a glTF model lit without a scene "
                 "file)");
  cmd.add_option("--environment-intensity", r.environment_intensity,
                 "--environment: multiplies the image's radiance (default 1)")
      ->check(real_number(0.0, 1e6));
  cmd.add_option("--environment-rotate", r.environment_rotate,
                 "--environment: turns the image about +Y, in degrees (default 0)")
      ->check(real_number(-360.0, 360.0));
  cmd.add_flag("--allow-outside-files", r.allow_outside_files, kOutsideFilesHelp);
  cmd.add_option("--isa", r.isa, isa_help());
}

void add_render_options(CLI::App& cmd, RenderCommand& r) {
  cmd.add_option("scene", r.scene, "Scene file (.json) or glTF model (.gltf/.glb)")->required();
  cmd.add_option("-o,--output", r.output,
                 "Output .png, .exr, .jpg, NAME_####.png, NAME_####.exr or .gif (default: <scene name>.png, or "
                 ".gif for --frames A-B)");
  add_scene_options(cmd, r);
  // Output only (the watch page keeps the tone curve, which it changes live).
  cmd.add_option("--view-transform", r.view_transform,
                 "PNG and GIF output through an OpenColorIO view, as Blender shows renders: Standard, Filmic, AgX "
                 "(the config's names; replaces the tone curve)");
  cmd.add_option("--look", r.look, "With --view-transform: the config's look, e.g. \"Medium High Contrast\"");
  cmd.add_option("--ocio-config", r.ocio_config,
                 "With --view-transform: the OpenColorIO config (default: Blender's, where Blender is installed)");
  cmd.add_option("--time", r.time,
                 "Path tracer: stop after about SECONDS with the best image so far, in whole passes of 8 samples a "
                 "pixel (each frame, each eye); the summary says how many samples each pixel got")
      ->check(real_number(0.001, 1e7));
  cmd.add_flag("--samples-debug", r.samples_debug,
               "Path tracer: also write NAME.samples.png, each pixel coloured by the samples it took");
  cmd.add_flag("--aa-debug", r.aa_debug,
               "Also write NAME.aa-refined.png (refined pixels green) and NAME.aa-depth.png (refinement depth)");
  CLI::Option* frames = cmd.add_option(
      "--frames", r.frames,
      "Render frames A-B, every S-th frame A-BxS, or a list 1,5,9-12 of the scene's animation: -o NAME.gif (looping "
      "animated GIF) or -o NAME_####.png (numbered)");
  cmd.add_option("--frame", r.frames, "Render frame N of the scene's animation")->excludes(frames);
  cmd.add_option(
      "--stereo", r.stereo,
      "Stereo from the camera's two eyes: " + kStereoModes.help() + " (replaces the scene's camera.stereo mode)");
  cmd.add_flag("--dither", r.dither, "GIF output: Floyd-Steinberg dithering (less banding, some noise)");
  CLI::Option* crop = cmd.add_option(
      "--crop", r.crop, "Render pixels [x0, x1) x [y0, y1) of the image only: the same pixels as in the whole render");
  cmd.add_option("--tile", r.tile,
                 "Render band I of N equal bands of rows (0-based), or auto: this Slurm array task's band")
      ->excludes(crop);
  cmd.add_option("--chunk", r.chunk,
                 "Render share I of N of the frames (consecutive, 0-based), or auto: this Slurm array task's");
  cmd.add_flag("--skip-existing", r.skip_existing,
               "Do not render frames whose output file is already there and complete (resume a stopped job)");
  cmd.add_flag("--exr-float", r.exr_float, "EXR output: 32-bit float channels (default: half floats)");
  cmd.add_option("--aov", r.aov,
                 "EXR output: layers beside the colour, any of albedo,normal,depth,variance (comma-separated)");
  cmd.add_flag("--denoise", r.denoise,
               "Denoise the image with its first hits' albedo, normal and depth and each pixel's variance "
               "(path tracer); an EXR keeps the raw image as layer \"raw\"; a --crop or --tile EXR gets the "
               "layers the denoiser needs, for rtcli merge --denoise");
  cmd.add_option("--resume", r.resume,
                 "Path tracer: add samples to an earlier render of the same scene and settings (its EXR, which holds "
                 "each pixel's sums): --spp is the total; the pixels are those of one render of them all");
  cmd.add_option("--denoiser", r.denoiser, "Which denoiser --denoise uses: " + denoisers().help());
  cmd.add_option("--stats", r.stats,
                 "Also write the render's figures (time, rays by kind, rays per pixel) as JSON to this file");
  cmd.add_flag("-q,--quiet", r.quiet, "Print nothing but errors and warnings");
  cmd.add_option("--progress", r.progress, "How progress is shown on the error stream: " + kProgressStyles.help());
}

}  // namespace rt
