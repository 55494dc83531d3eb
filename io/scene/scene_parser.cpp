#include "io/scene/scene_parser.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "io/base/input_file.h"
#include "io/json/locate.h"
#include "io/scene/animation_parser.h"
#include "io/scene/camera_parser.h"
#include "io/scene/light_parser.h"
#include "io/scene/node_parser.h"

namespace rt {
namespace {

constexpr NumberRule kImageSize{1, kMaxImageSide, false, false, true};
constexpr NumberRule kMaxDepth{0, kMaxRecursionDepth, false, false, true};
constexpr NumberRule kSeed{0, 9007199254740992.0, false, false, true};  // 2^53: exact in a double
constexpr NumberRule kSamplesPerAxis{1, kMaxSamplesPerAxis, false, false, true};
constexpr NumberRule kGlossySamples{1, kMaxGlossySamples, false, false, true};
constexpr NumberRule kShadowSamples{1, kMaxShadowSamples, false, false, true};
constexpr NumberRule kThreshold{0, 1, false, false, false};  // a difference of displayed values
constexpr NumberRule kAdaptiveDepth{0, kMaxAdaptiveDepth, false, false, true};
constexpr NumberRule kExposure{-kMaxExposure, kMaxExposure, false, false, false};  // stops
constexpr NumberRule kSamplesPerPixel{1, kMaxSamplesPerPixel, false, false, true};
constexpr NumberRule kNoiseThreshold{0, 1, false, false, false};  // a relative error
constexpr NumberRule kRotateDegrees{-360, 360, false, false, false};

// render.antialias: every key is read whatever the mode, so that --aa can switch modes and keep
// the scene's parameters.
void parse_antialias(const JsonReader& r, const Json& v, const std::string& ptr, const std::vector<std::string>& modes,
                     AntialiasSettings& aa) {
  ObjectReader a(r, v, ptr);
  if (const Json* mode = a.get("mode", true, join_quoted(modes))) {
    if (const auto k = read_choice(r, *mode, a.child("mode"), modes)) aa.mode = modes[*k];
  }
  if (const auto n = a.number("samples", kSamplesPerAxis)) aa.samples = static_cast<int>(*n);
  if (const Json* j = a.get("jitter")) {
    if (j->is_boolean()) aa.jitter = j->get<bool>();
    else r.expected(a.child("jitter"), "true or false", *j);
  }
  if (const auto t = a.number("threshold", kThreshold)) aa.threshold = static_cast<float>(*t);
  if (const auto d = a.number("max_depth", kAdaptiveDepth)) aa.max_depth = static_cast<int>(*d);
  if (const Json* p = a.get("positions")) {
    if (const auto k = read_choice(r, *p, a.child("positions"), kSamplePositions)) aa.positions = *k;
  }
  a.finish();
}

// background as an object: {"environment": FILE, "intensity": k >= 0, "rotate": degrees}.
std::optional<EnvironmentReference> parse_environment(const JsonReader& r, const Json& v, const std::string& ptr,
                                                      const std::string& folder) {
  ObjectReader o(r, v, ptr);
  EnvironmentReference e;
  bool ok = false;
  if (const Json* f = o.get("environment", true, "the path of a Radiance .hdr or OpenEXR .exr image")) {
    if (const auto file = read_string(r, *f, o.child("environment"))) {
      if (file->empty()) {
        r.expected(o.child("environment"), "the path of a Radiance .hdr or OpenEXR .exr image", *f);
      } else {
        e.file = *file;
        e.resolved_path = resolve_path(folder, *file);
        e.pointer = o.child("environment");
        ok = true;
      }
    }
  }
  if (const auto k = o.number("intensity", kNonNegative)) e.intensity = static_cast<float>(*k);
  if (const auto d = o.number("rotate", kRotateDegrees)) e.rotate = static_cast<float>(*d);
  o.finish();
  if (!ok) return std::nullopt;
  return e;
}

void parse_render(const JsonReader& r, const Json& v, const std::string& ptr, const LoadOptions& options,
                  RenderSettings& s) {
  ObjectReader o(r, v, ptr);
  if (const auto w = o.number("width", kImageSize)) s.width = static_cast<int>(*w);
  if (const auto h = o.number("height", kImageSize)) s.height = static_cast<int>(*h);
  if (const auto d = o.number("max_depth", kMaxDepth)) s.max_depth = static_cast<int>(*d);
  if (const auto seed = o.number("seed", kSeed)) s.seed = static_cast<uint64_t>(*seed);
  if (const auto n = o.number("glossy_samples", kGlossySamples)) s.glossy_samples = static_cast<int>(*n);
  if (const auto n = o.number("shadow_samples", kShadowSamples)) s.shadow_samples = static_cast<int>(*n);
  if (const Json* m = o.get("sampler")) {
    if (const auto k = read_choice(r, *m, o.child("sampler"), kSampleSequences)) s.sampler = *k;
  }
  if (const Json* m = o.get("secondary_shadows")) {
    if (const auto k = read_choice(r, *m, o.child("secondary_shadows"), kSecondaryShadows))
      s.scale_secondary_shadows = *k;
  }
  if (const auto e = o.number("exposure", kExposure)) s.display.exposure = static_cast<float>(*e);
  if (const auto n = o.number("samples_per_pixel", kSamplesPerPixel)) s.path.samples_per_pixel = static_cast<int>(*n);
  if (const auto t = o.number("noise_threshold", kNoiseThreshold)) s.path.noise_threshold = static_cast<float>(*t);
  if (const auto c = o.number("clamp", kNonNegative)) s.path.clamp = static_cast<float>(*c);
  if (const Json* t = o.get("tone_map")) {
    if (const auto k = read_choice(r, *t, o.child("tone_map"), kToneMaps)) s.display.curve = *k;
  }
  if (const Json* i = o.get("integrator")) {
    if (const auto k = read_choice(r, *i, o.child("integrator"), options.integrators))
      s.integrator = options.integrators[*k];
  }
  if (const Json* aa = o.get("antialias"))
    parse_antialias(r, *aa, o.child("antialias"), options.pixel_samplers, s.antialias);
  o.finish();
}

// The image's size once every file's render block is read: at the last one (ptr).
void check_render_size(const JsonReader& r, const RenderSettings& s, const std::string& ptr) {
  if (pixel_count(s) > kMaxPixels) {
    r.error(ptr,
            "expected at most " + std::to_string(kMaxPixels) + " pixels (width x height), found " +
                std::to_string(s.width) + " x " + std::to_string(s.height) + " = " + std::to_string(pixel_count(s)) +
                " (docs/errors-and-limits.md, \"Limits\")",
            Anchor::kKey);
  } else if (max_camera_rays_per_frame(s) > kCameraRaysWarning) {
    r.warning(ptr,
              "this render can trace up to " + std::to_string(max_camera_rays_per_frame(s)) +
                  " camera rays per frame (pixels x the most rays per pixel); expect it to take a long time",
              Anchor::kKey);
  }
}

// The texture keys of one material. A texture replaces kd (or ks) and kd multiplies it, so that
// kd can tint it; without an explicit kd that is white.
void parse_texture_slots(const JsonReader& r, ObjectReader& o, const std::string& folder, MaterialDescription& m) {
  Material& mat = m.material;
  if (const Json* t = o.get("texture")) {
    m.texture = parse_texture_slot(r, *t, o.child("texture"), folder, TextureEncoding::kSrgb, mat.texture.mapping);
    if (!o.has("kd")) mat.kd = Vec3(1.0f);
  }
  if (const Json* t = o.get("specular_texture")) {
    m.specular_texture = parse_texture_slot(r, *t, o.child("specular_texture"), folder, TextureEncoding::kSrgb,
                                            mat.specular_texture.mapping);
    if (!o.has("ks")) mat.ks = Vec3(1.0f);
  }
  if (const Json* t = o.get("bump")) {
    m.bump = parse_texture_slot(r, *t, o.child("bump"), folder, TextureEncoding::kLinear, mat.bump.height.mapping,
                                [&](ObjectReader& b) {
                                  if (const auto s = b.number("strength")) mat.bump.strength = static_cast<float>(*s);
                                  if (const auto e = b.number("epsilon", NumberRule{0, 1, true, false, false}))
                                    mat.bump.epsilon = static_cast<float>(*e);
                                });
  }
  if (const Json* t = o.get("normal_map")) {
    m.normal_map = parse_texture_slot(r, *t, o.child("normal_map"), folder, TextureEncoding::kLinear,
                                      mat.normal_map.map.mapping, [&](ObjectReader& n) {
                                        if (const auto s = n.number("strength"))
                                          mat.normal_map.scale = static_cast<float>(*s);
                                      });
  }
}

// A file's materials, each replacing one of the same name from an earlier file.
void parse_materials(const JsonReader& r, const Json& v, const std::string& ptr, const std::string& folder,
                     std::vector<MaterialDescription>& out) {
  if (!v.is_object()) {
    r.expected(ptr, "an object mapping material names to materials", v);
    return;
  }
  for (const auto& item : v.items()) {
    MaterialDescription m;
    m.name = item.key();
    ObjectReader o(r, item.value(), pointer_child(ptr, item.key()));
    Material& mat = m.material;
    if (const auto kd = o.color("kd")) mat.kd = *kd;
    if (const auto ks = o.color("ks")) mat.ks = *ks;
    if (const auto n = o.number("shininess", kPositive)) mat.shininess = static_cast<float>(*n);
    // The proposal's own rules, spelt "ks": reflection weighted by ks, glossy width 1 / (1 + ks).
    // A string value may only be "ks"; anything else is reported once, by read_choice.
    const auto spelt = [&](std::string_view key, bool& is_ks) {
      const Json* value = o.get(key);
      if (!value || !value->is_string()) return false;
      is_ks = read_choice(r, *value, o.child(key), {"ks"}).has_value();
      return true;
    };
    bool is_ks = false;
    if (spelt("reflectivity", is_ks)) {
      if (is_ks) mat.reflectivity = glm::min(mat.ks, Vec3(1.0f));
    } else if (const auto w = o.weight("reflectivity")) {
      mat.reflectivity = *w;
    }
    if (const auto w = o.weight("transmission")) mat.transmission = *w;
    if (const auto n = o.number("ior", kPositive)) mat.ior = static_cast<float>(*n);
    if (const auto a = o.color("absorption")) mat.absorption = *a;
    if (const auto e = o.color("emission")) mat.emission = *e;
    if (spelt("glossy", is_ks)) {
      if (is_ks) mat.glossy = 1.0f / (1.0f + (mat.ks.x + mat.ks.y + mat.ks.z) / 3.0f);
    } else if (const auto g = o.number("glossy", kNonNegative)) {
      mat.glossy = static_cast<float>(*g);
    }
    parse_texture_slots(r, o, folder, m);
    o.finish();
    const auto same =
        std::find_if(out.begin(), out.end(), [&](const MaterialDescription& d) { return d.name == m.name; });
    if (same != out.end()) *same = std::move(m);
    else out.push_back(std::move(m));
  }
}

}  // namespace

std::optional<SceneDescription> parse_scene(const SceneSources& sources, const LoadOptions& options,
                                            Diagnostics& diags) {
  const size_t errors_before = diags.error_count();
  SceneDescription scene = parse_scene_partial(sources, options, diags);
  if (diags.error_count() > errors_before) return std::nullopt;
  return scene;
}

SceneDescription parse_scene_partial(const SceneSources& sources, const LoadOptions& options, Diagnostics& diags) {
  const JsonReader r(sources.scene().doc, diags, sources.places());
  SceneDescription scene;
  scene.path = sources.scene().doc.path;
  // Every file's keys but its nodes, included files first: a later file's value wins (a
  // material or template by name, each render setting by key; lights add up).
  std::optional<std::string> render_at, camera_at;
  std::map<std::string, TemplateSource> templates;
  struct NodeList {
    const Json* nodes;
    std::string pointer, folder;
  };
  std::vector<NodeList> node_lists;
  for (const auto& file : sources.files()) {
    const std::string& folder = file->folder;
    ObjectReader top(r, file->doc.root, file->prefix);
    top.get("$schema");  // editors use it to find the schema; we don't need it
    top.get("include");  // read with the file (io/scene/scene_sources.h)
    if (const Json* v = top.get("render")) {
      parse_render(r, *v, top.child("render"), options, scene.render);
      render_at = top.child("render");
    }
    if (const Json* v = top.get("camera")) {
      scene.camera = CameraDescription{};
      parse_camera(r, *v, top.child("camera"), scene.camera);
      camera_at = top.child("camera");
    }
    if (const Json* bg = top.get("background")) {
      scene.environment.reset();
      scene.background = Vec3(0.0f);
      if (bg->is_object()) {
        scene.environment = parse_environment(r, *bg, top.child("background"), folder);
      } else if (const auto c = read_color(r, *bg, top.child("background"))) {
        scene.background = *c;
      }
    }
    if (const auto ambient = top.color("ambient")) scene.ambient = *ambient;
    if (const Json* v = top.get("materials")) parse_materials(r, *v, top.child("materials"), folder, scene.materials);
    if (const Json* v = top.get("lights")) parse_lights(r, *v, top.child("lights"), scene.lights, scene.light_pointers);
    if (const Json* v = top.get("templates")) {
      if (!v->is_object()) {
        r.expected(top.child("templates"), "an object mapping template names to nodes", *v);
      } else {
        for (const auto& item : v->items())
          templates[item.key()] =
              TemplateSource{&item.value(), pointer_child(top.child("templates"), item.key()), folder};
      }
    }
    if (const Json* v = top.get("nodes")) node_lists.push_back(NodeList{v, top.child("nodes"), folder});
    if (const Json* v = top.get("animation"))
      scene.animation = parse_animation(r, *v, top.child("animation"), options.limits.animation_keys);
    top.finish();
  }
  // Required of the scene with its includes together; reported on the scene file.
  ObjectReader scene_top(r, sources.scene().doc.root, sources.scene().prefix);
  if (!camera_at) scene_top.get("camera", true, "an object with position, look_at, up and fov");
  if (node_lists.empty()) scene_top.get("nodes", true, "an array of nodes");
  check_render_size(r, scene.render, render_at.value_or(""));
  // The nodes, once every material and template is known.
  NodeParseContext ctx{.reader = r,
                       .scene_folder = "",
                       .materials = scene.materials,
                       .max_nodes = options.limits.nodes,
                       .templates = std::move(templates)};
  for (const NodeList& list : node_lists) {
    ctx.scene_folder = list.folder;
    std::vector<NodeDescription> nodes = parse_nodes(ctx, *list.nodes, list.pointer);
    for (NodeDescription& n : nodes) scene.nodes.push_back(std::move(n));
  }
  return scene;
}

}  // namespace rt
