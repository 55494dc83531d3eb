#include "io/assemble/scene_builder.h"

#include <algorithm>
#include <cmath>

#include "core/thread_count.h"
#include "io/assemble/csg_operands.h"
#include "io/assemble/load_cache.h"
#include "io/assemble/model_framing.h"
#include "io/assemble/model_library.h"
#include "io/assemble/placement_warnings.h"
#include "io/assemble/scene_warnings.h"
#include "io/assemble/texture_library.h"
#include "io/gltf/loader.h"
#include "io/json/locate.h"
#include "io/json/reader.h"
#include "io/scene/camera_parser.h"

namespace rt {
namespace {

class Builder {
 public:
  // The scene's own materials come first, so their indices stay those of the description;
  // glTF files append theirs as they are loaded.
  Builder(const SceneDescription& desc, PlaceFinder places, const LoadOptions& options, Diagnostics& diags)
      : desc_(desc),
        places_(std::move(places)),
        options_(options),
        diags_(diags),
        bvh_options_{resolve_thread_count(options.threads), options.isa} {
    // The scene file's tracks were counted when they were parsed; glTF files' come on top.
    if (desc_.animation)
      for (const TrackDescription& t : desc_.animation->tracks) usage_.animation_keys += t.track.keys->times.size();
    for (const MaterialDescription& m : desc_.materials) assets_.materials.push_back(with_textures(m));
  }

  void add_nodes(const std::vector<NodeDescription>& nodes, int32_t parent) {
    for (const NodeDescription& node : nodes) {
      if (over_limit()) return;
      const auto index = static_cast<int32_t>(nodes_.size());
      SceneNode n;
      n.name = node.name;
      n.parent = parent;
      n.trs = node.transform.trs;
      n.matrix = node.transform.matrix;
      if (node.shape) {
        n.shape = node.shape;
        n.shape_material = node.material.value_or(0);
        take_instances(1, node.pointer);
      }
      push_node(std::move(n), node.pointer, false);
      scene_index_[&node] = static_cast<uint32_t>(index);
      if (node.mesh) add_model(*node.mesh, index, node.material);
      in_csg_ += node.csg.has_value();
      add_nodes(node.children, index);
      in_csg_ -= node.csg.has_value();
      // The outermost CSG node takes its subtree's geometry into one solid.
      if (node.csg && in_csg_ == 0 && !over_limit())
        if (auto t = make_csg_template(CsgSource{node, scene_index_, assets_}, nodes_, report_))
          csgs_.push_back(std::move(*t));
    }
  }

  void add_animation() {
    if (!desc_.animation) return;
    const AnimationDescription& a = *desc_.animation;
    std::vector<std::string> names;
    for (const SceneNode& n : nodes_)
      if (!n.name.empty()) names.push_back(n.name);
    for (const TrackDescription& t : a.tracks) {
      // A scene node of that name, else every node of that name inside the glTF files the scene
      // places (a file placed twice moves in both places).
      std::vector<size_t> in_scene, in_files;
      for (size_t i = 0; i < nodes_.size(); ++i)
        if (nodes_[i].name == t.node) (from_file_[i] ? in_files : in_scene).push_back(i);
      const std::vector<size_t> found = in_scene.empty() ? in_files : std::vector<size_t>{in_scene.front()};
      if (found.empty()) {
        std::string message =
            "expected the name of a node under /nodes or inside a glTF file they place, found \"" + t.node + "\"";
        if (const auto near = closest_match(t.node, names)) message += " (did you mean \"" + *near + "\"?)";
        error(t.pointer + "/node", message);
        continue;
      }
      for (const size_t node : found) {
        if (nodes_[node].matrix) {
          error(t.pointer + "/node", "expected a node with translate/rotate/scale to animate, found \"" + t.node +
                                         "\" placed by a matrix (" +
                                         (from_file_[node] ? "in the glTF file placed at " : "") + pointers_[node] +
                                         ")");
          break;
        }
        Track track = t.track;
        track.node = static_cast<uint32_t>(node);
        tracks_.push_back(std::move(track));
      }
    }
  }

  std::optional<BuiltScene> finish() {
    SceneGraph g;
    g.nodes = std::move(nodes_);
    g.csgs = std::move(csgs_);
    g.tracks = std::move(tracks_);
    const auto color = [](const std::optional<std::array<float, 3>>& c, Vec3 otherwise) {
      return c ? Vec3((*c)[0], (*c)[1], (*c)[2]) : otherwise;
    };
    g.background = Environment(color(options_.background, desc_.background));
    if (options_.environment) {  // --environment replaces the scene's background, colour or image
      const LoadOptions::EnvironmentChoice& e = *options_.environment;
      std::string why;
      if (auto image = textures_.environment(e.path, why, files_))
        g.background = Environment(std::move(image), e.intensity, e.rotate);
      else diags_.file_error(e.path, "--environment: " + why);
    } else if (desc_.frame_the_model && file_world_ && !options_.background) {  // a model's own world
      const ImportedWorld& w = *file_world_;
      std::string why;
      if (w.image.empty()) g.background = Environment(w.color);
      else if (auto image = textures_.environment(w.image, why, files_))
        g.background = Environment(std::move(image), w.intensity, w.rotate);
      else diags_.file_error(w.image, "the world image of the glTF file's scene (rtcli_world): " + why);
    } else if (desc_.environment && !options_.background) {  // --background replaces an image too
      const EnvironmentReference& e = *desc_.environment;
      std::string why;
      if (auto image = textures_.environment(e.resolved_path, why, files_))
        g.background = Environment(std::move(image), e.intensity, e.rotate);
      else error(e.pointer, why);
    }
    g.ambient = color(options_.ambient, desc_.ambient);
    set_timeline(g);
    const CameraDescription& c = desc_.camera;
    g.camera.camera = make_camera(c);
    for (const Light& l : desc_.lights) g.lights.push_back(LightPlacement{l, -1});
    g.lights.insert(g.lights.end(), file_lights_.begin(), file_lights_.end());
    if (!choose_camera(g)) return std::nullopt;
    // Masks point into the meshes and textures: made once the assets are where they stay.
    auto assets = std::make_shared<SceneAssets>(std::move(assets_));
    for (const SceneNode& node : g.nodes)
      for (const NodeMesh& nm : node.meshes) assets->add_mask(nm.mesh, nm.material, path_traced());
    g.assets = std::move(assets);

    // The timeline's first frame, placed once: its problems are errors at the nodes concerned
    // (nodes from glTF files scaled to nothing are parts hidden on purpose, and simply not drawn).
    const Pose rest = g.pose(g.timeline.first_frame);
    std::vector<PlacementIssue> issues;
    PrimitiveSet placed = g.place(rest, &issues);
    warn_hidden_files(g, pointers_, from_file_, issues, report_);
    for (const PlacementIssue& issue : issues) {
      if (issue.kind == PlacementIssue::kSingular && from_file_[issue.node]) continue;
      error(pointers_[issue.node],
            issue.kind == PlacementIssue::kSingular
                ? "expected an invertible world transform, found a singular one (the transforms above this node "
                  "multiply to a flattening scale)"
                : "expected a shape within the single-precision range (|x| < 3.4e38) after its transforms, found one "
                  "that reaches infinity");
    }
    warn_stacked_copies(g, rest, pointers_, report_);
    warn_empty_csgs(g, rest, pointers_, report_);
    if (desc_.frame_the_model && !frame(g, placed)) return std::nullopt;
    if (diags_.error_count() > errors_before_) return std::nullopt;
    const std::vector<Aabb> geometry = geometry_bounds(placed);
    // The frame a render shows first, with its BVH (validate builds none); another than the
    // timeline's first is posed anew, and the first frame's placement is not built at all.
    const int frame = options_.frame.value_or(g.timeline.first_frame);
    Scene scene = !options_.build_bvh               ? g.at(rest, PrimitiveSet{}, bvh_options_)
                  : frame == g.timeline.first_frame ? g.at(rest, std::move(placed), bvh_options_)
                                                    : g.at(g.pose(frame), bvh_options_);
    if (!diags_.has_errors()) {  // a scene with errors (a node left out) would get false alarms
      warn_camera_inside(g, rest, scene.camera.position, pointers_, report_);
      warn_unlit_or_empty(scene, path_traced(), geometry, light_pointers(g), report_);
    }
    return BuiltScene{std::move(g), frame, std::move(scene)};
  }

  std::vector<std::string> take_files() { return std::move(files_); }

  // Whether the render will path-trace (the scene's integrator, or --integrator's): BLEND's
  // coverage and the unlit-scene warning depend on it. io does not link the renderer: by name.
  bool path_traced() const { return options_.integrator.value_or(desc_.render.integrator) == "path"; }

  // Per light of the graph, where it is described: the scene's lights, then the glTF files'
  // (their nodes' pointers); empty for the light rtcli adds to a model on its own.
  std::vector<std::string> light_pointers(const SceneGraph& g) const {
    std::vector<std::string> out;
    for (size_t i = 0; i < desc_.lights.size(); ++i)
      out.push_back(i < desc_.light_pointers.size() ? desc_.light_pointers[i] : pointer_child("/lights", i));
    for (const LightPlacement& l : file_lights_) out.push_back(pointers_[static_cast<size_t>(l.node)]);
    out.resize(g.lights.size());
    return out;
  }

 private:
  void push_node(SceneNode n, const std::string& pointer, bool from_file) {
    nodes_.push_back(std::move(n));
    pointers_.push_back(pointer);
    from_file_.push_back(from_file);
  }

  void set_timeline(SceneGraph& g) const {
    const AnimationDescription* a = desc_.animation ? &*desc_.animation : nullptr;
    // A scene file's animation.fps (default 30); a model on its own, --fps (default 24, Blender's).
    g.timeline.fps = a ? a->fps : desc_.frame_the_model ? options_.fps.value_or(kModelFps) : 30.0f;
    float end = 0.0f;
    for (const Track& t : g.tracks) end = std::max(end, t.end());
    g.animated = !g.tracks.empty() || a;
    g.timeline.first_frame = a && a->first_frame ? *a->first_frame : 0;
    // Default: up to the frame of the last key (rounded up, so that no key is cut off).
    const double last = std::ceil(static_cast<double>(end) * g.timeline.fps - 1e-3);
    g.timeline.last_frame =
        a && a->last_frame ? *a->last_frame : std::max(g.timeline.first_frame, static_cast<int>(std::min(last, 1e6)));
  }

  // --camera NAME: a glTF camera by its name or its node's, instead of the scene's camera.
  bool choose_camera(SceneGraph& g) {
    if (!options_.camera) return true;
    std::vector<std::string> names;
    for (const CameraPlacement& c : cameras_) {
      if (c.name == *options_.camera || g.nodes[static_cast<size_t>(c.node)].name == *options_.camera) {
        g.camera = c;
        g.camera.camera.stereo = make_camera(desc_.camera).stereo;  // the scene's stereo settings still apply
        return true;
      }
      names.push_back(c.name);
    }
    diags_.file_error(desc_.path,
                      "--camera: expected the name of a camera in the scene's glTF files" +
                          (names.empty() ? std::string(" (there are none)") : " (" + join_quoted(names) + ")") +
                          ", found \"" + *options_.camera + "\"");
    return false;
  }

  // The model's framing camera and light (io/assemble/model_framing.h), an error if it has none.
  bool frame(SceneGraph& g, const PrimitiveSet& placed) {
    const float aspect = static_cast<float>(desc_.render.width) / static_cast<float>(desc_.render.height);
    std::optional<CameraPlacement> file_camera;
    if (!cameras_.empty()) file_camera = cameras_.front();
    std::string error;
    if (frame_model(g, placed, aspect, options_.camera.has_value(), file_camera, error)) return true;
    diags_.file_error(desc_.path, error);
    return false;
  }

  // The material with its slots pointing at loaded textures; a slot whose file failed stays empty
  // (the error is recorded, so the scene is not built).
  Material with_textures(const MaterialDescription& m) {
    Material out = m.material;
    const auto fill = [&](const std::optional<TextureFileReference>& ref, TextureSlot& slot) {
      if (!ref || over_limit()) return;
      slot.texture = textures_.load(*ref, report_, files_);
    };
    fill(m.texture, out.texture);
    fill(m.specular_texture, out.specular_texture);
    fill(m.bump, out.bump.height);
    fill(m.normal_map, out.normal_map.map);
    return out;
  }

  // Shapes and placed mesh primitives together; one error when the limit is passed, then stop.
  bool take_instances(uint64_t count, const std::string& pointer) {
    instances_ += count;
    if (instances_ <= options_.limits.instances) return true;
    limit_error(pointer, "expected at most " + std::to_string(options_.limits.instances) +
                             " shapes and placed mesh primitives in a scene, found more");
    return false;
  }

  // A glTF file's node tree, grafted under scene node `parent` (or its one named mesh, carried by
  // `parent` itself), with the file's animation tracks moved onto the grafted nodes.
  void add_model(const MeshReference& ref, int32_t parent, std::optional<uint32_t> material_override) {
    const LoadedModel* loaded = models_.load(ref);
    if (!loaded) return;
    const ImportedModel& model = loaded->model;
    // The node's "material" replaces them all; "materials" in the mesh object replaces by name.
    for (const MaterialOverride& o : ref.materials) {
      const auto& names = model.material_names;
      if (std::find(names.begin(), names.end(), o.file_material) != names.end()) continue;
      std::string message = "expected the name of a material in \"" + ref.file + "\"";
      if (!names.empty() && names.size() <= 12) message += " (" + join_quoted(names) + ")";
      message += ", found \"" + o.file_material + "\"";
      if (const auto near = closest_match(o.file_material, names)) message += " (did you mean \"" + *near + "\"?)";
      error(o.pointer, message);
    }
    const auto material_of = [&](const LoadedPrimitive& p) {
      if (material_override) return *material_override;
      if (p.file_material >= 0)
        for (const MaterialOverride& o : ref.materials)
          if (model.material_names[static_cast<size_t>(p.file_material)] == o.file_material) return o.material;
      return p.material;
    };
    const auto meshes_of = [&](int32_t mesh) {
      std::vector<NodeMesh> out;
      if (mesh < 0) return out;
      for (const LoadedPrimitive& p : loaded->meshes[static_cast<size_t>(mesh)])
        out.push_back(NodeMesh{p.geometry, material_of(p)});
      return out;
    };
    size_t placed = 0;
    if (ref.mesh_name) {
      SceneNode& carrier = nodes_[static_cast<size_t>(parent)];
      carrier.meshes = meshes_of(model.nodes.front().mesh);
      placed = carrier.meshes.size();
      take_instances(placed, ref.pointer);
    } else {
      const auto base = static_cast<int32_t>(nodes_.size());
      for (const ImportedNode& in : model.nodes) {
        SceneNode n;
        n.name = in.name;
        n.parent = in.parent >= 0 ? base + in.parent : parent;
        n.trs = in.trs;
        n.matrix = in.matrix;
        n.meshes = meshes_of(in.mesh);
        n.instancing = in.instancing;
        const size_t copies = n.meshes.size() * std::max<size_t>(1, n.instancing.size());
        placed += copies;
        if (!take_instances(copies, ref.pointer)) return;
        push_node(std::move(n), ref.pointer, true);
      }
      for (Track t : model.tracks) {
        t.node += static_cast<uint32_t>(base);
        tracks_.push_back(std::move(t));
      }
      for (CameraPlacement c : model.cameras) {
        c.node += base;
        cameras_.push_back(std::move(c));
      }
      for (LightPlacement l : model.lights) {
        l.node += base;
        file_lights_.push_back(l);
      }
      if (model.world && !file_world_) file_world_ = *model.world;
    }
    if (placed == 0) warning(ref.pointer, "\"" + ref.file + "\" has no triangles to render");
  }

  void limit_error(const std::string& pointer, const std::string& message) { report_.over_limit(pointer, message); }
  void error(const std::string& pointer, std::string message) { report_.error(pointer, std::move(message)); }
  void warning(const std::string& pointer, std::string message) { report_.warning(pointer, std::move(message)); }
  bool over_limit() const { return report_.stopped_by_limit(); }

  // Reports on the scene file: at its pointers, with line:column. A model rendered on its own
  // has no scene file: its description's pointers are not the user's, so none is shown.
  static Reporter scene_reporter(const SceneDescription& desc, const PlaceFinder& places, Diagnostics& diags) {
    if (places) return Reporter(diags, desc.path, places);
    return Reporter(diags, desc.path, {}, false);
  }

  const SceneDescription& desc_;
  const PlaceFinder places_;
  const LoadOptions& options_;
  Diagnostics& diags_;
  const BvhBuildOptions bvh_options_;
  const size_t errors_before_ = diags_.error_count();
  Reporter report_ = scene_reporter(desc_, places_, diags_);
  SceneAssets assets_;
  LimitUsage usage_;
  TextureLibrary textures_{assets_.textures, options_.limits, usage_, options_.cache};
  std::vector<SceneNode> nodes_;
  std::vector<std::string> pointers_;  // per node: where the scene file describes it
  std::vector<bool> from_file_;        // per node: grafted from a glTF file
  std::map<const NodeDescription*, uint32_t> scene_index_;
  std::vector<CsgTemplate> csgs_;
  int in_csg_ = 0;  // CSG nodes enclosing the nodes being added
  std::vector<Track> tracks_;
  std::vector<CameraPlacement> cameras_;  // from glTF files, node indices into nodes_
  std::vector<LightPlacement> file_lights_;
  std::optional<ImportedWorld> file_world_;  // the first glTF file's rtcli_world: a model on its own shows it
  std::vector<std::string> files_;
  ModelLibrary models_{assets_, textures_, options_, usage_, bvh_options_, files_, report_};
  uint64_t instances_ = 0;
};

}  // namespace

std::optional<BuiltScene> build_scene(const SceneDescription& desc, PlaceFinder places, const LoadOptions& options,
                                      Diagnostics& diags, std::vector<std::string>* files) {
  Builder builder(desc, std::move(places), options, diags);
  builder.add_nodes(desc.nodes, -1);
  builder.add_animation();
  // After finish(): it reads the environment image, which is an input like every other file.
  std::optional<BuiltScene> built = builder.finish();
  if (files) *files = builder.take_files();
  return built;
}

}  // namespace rt
