#include "io/scene_builder.h"

#include <cstdio>
#include <limits>
#include <map>

#include "core/thread_count.h"
#include "io/gltf_loader.h"
#include "io/json_reader.h"
#include "io/texture_file.h"

namespace rt {
namespace {

bool is_finite(const Aabb& box) { return rt::is_finite(box.lo) && rt::is_finite(box.hi); }

// Half the float range: the difference of two such coordinates (a triangle's edge) is finite.
constexpr float kMaxVertexCoordinate = std::numeric_limits<float>::max() / 2;

std::string format_point(Vec3 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%g, %g, %g]", p.x, p.y, p.z);
  return buf;
}

class Builder {
 public:
  // The scene's own materials come first, so their indices stay those of the description;
  // glTF files append theirs as they are loaded.
  Builder(const SceneDescription& desc, const JsonDocument* source, const LoadOptions& options, Diagnostics& diags)
      : desc_(desc), source_(source), options_(options), diags_(diags) {
    for (const MaterialDescription& m : desc_.materials) materials_.push_back(with_textures(m));
  }

  void add_nodes(const std::vector<NodeDescription>& nodes, const Mat4& parent) {
    for (const NodeDescription& node : nodes) {
      if (over_limit_) return;
      const Mat4 world = parent * node.local;
      if (node.shape || node.mesh) {
        const auto transform = make_transform(world);
        if (!transform) {
          error(node.pointer,
                "expected an invertible world transform, found a singular one (the transforms above this "
                "node multiply to a flattening scale)");
        } else if (node.shape) {
          add_shape(AnalyticShape{*node.shape, node.material.value_or(0), *transform}, node.pointer);
        } else {
          add_mesh(*node.mesh, world, node.material);
        }
      }
      add_nodes(node.children, world);
    }
  }

  Scene finish() {
    Scene scene;
    scene.camera =
        Camera::look_at(desc_.camera.position, desc_.camera.look_at, desc_.camera.up, desc_.camera.fov_degrees);
    scene.camera.aperture = desc_.camera.aperture;
    scene.camera.focus_distance =
        desc_.camera.focus_distance.value_or(glm::length(desc_.camera.look_at - desc_.camera.position));
    scene.background = desc_.background;
    scene.ambient = desc_.ambient;
    scene.lights = desc_.lights;
    scene.materials = std::move(materials_);
    scene.textures = std::move(textures_);
    uint32_t first = 0;
    for (const TriangleMesh& m : meshes_) {
      scene.mesh_first_triangle.push_back(first);
      first += static_cast<uint32_t>(m.triangle_count());
    }
    if (options_.build_bvh)
      scene.bvh =
          Bvh(make_primitive_set(meshes_, std::move(shapes_)), BvhBuildOptions{resolve_thread_count(options_.threads)});
    scene.meshes = std::move(meshes_);
    return scene;
  }

  std::vector<std::string> take_files() { return std::move(files_); }

 private:
  // The material with its slots pointing at loaded textures; a slot whose file failed stays empty
  // (the error is recorded, so the scene is not built).
  Material with_textures(const MaterialDescription& m) {
    Material out = m.material;
    const auto fill = [&](const std::optional<TextureFileReference>& ref, TextureSlot& slot) {
      if (ref) slot.texture = texture_index(*ref);
    };
    fill(m.texture, out.texture);
    fill(m.specular_texture, out.specular_texture);
    fill(m.bump, out.bump.height);
    fill(m.normal_map, out.normal_map.map);
    return out;
  }

  // Each file is loaded once per encoding (a colour texture is decoded from sRGB, a height map not).
  uint32_t texture_index(const TextureFileReference& ref) {
    const std::string key = ref.resolved_path + (ref.encoding == TextureEncoding::kSrgb ? "\nsrgb" : "\nlinear");
    if (const auto it = texture_indices_.find(key); it != texture_indices_.end()) return it->second;
    const LoadLimits& limits = options_.limits;
    const uint64_t budget = std::min(limits.texture_texels, limits.scene_texels - texels_);
    std::string why;
    auto texture = load_texture(ref.resolved_path, ref.encoding, budget, why);
    uint32_t index = kNoTexture;
    if (!texture) {
      if (budget < limits.texture_texels)
        why += " (all the scene's textures together may hold at most " + std::to_string(limits.scene_texels) +
               " texels; README, \"Limits\")";
      // load_texture says what it found: a size ("expected an image of 1 to N texels, found ...")
      // or why the file could not be read.
      error(ref.pointer, why.rfind("expected", 0) == 0 ? why : "expected a readable PNG or JPEG image; " + why);
    } else {
      for (int level = 0; level < texture->level_count(); ++level)
        texels_ += static_cast<uint64_t>(texture->width(level)) * static_cast<uint64_t>(texture->height(level));
      files_.push_back(ref.resolved_path);
      index = static_cast<uint32_t>(textures_.size());
      textures_.push_back(std::move(*texture));
    }
    texture_indices_.emplace(key, index);
    return index;
  }

  // Shapes and placed mesh primitives together; one error when the limit is passed, then stop.
  bool take_instance(const std::string& pointer) {
    if (++instances_ <= options_.limits.instances) return true;
    limit_error(pointer, "expected at most " + std::to_string(options_.limits.instances) +
                             " shapes and placed mesh primitives in a scene, found more");
    return false;
  }

  void add_shape(const AnalyticShape& shape, const std::string& pointer) {
    if (!take_instance(pointer)) return;
    const Aabb bounds = world_bounds(shape);
    if (!is_finite(bounds)) {
      error(pointer,
            "expected a shape within the single-precision range (|x| < 3.4e38) after its transforms, found "
            "one that reaches infinity");
      return;
    }
    shapes_.push_back(shape);
  }

  void add_mesh(const MeshReference& ref, const Mat4& world, std::optional<uint32_t> material_override) {
    const std::string key = ref.resolved_path + '\n' + ref.mesh_name.value_or("");
    auto it = models_.find(key);
    if (it == models_.end()) {
      ImportError why;
      auto model = import_gltf(ref.resolved_path, ref.mesh_name, options_.limits, why);
      if (model) files_.insert(files_.end(), model->files.begin(), model->files.end());
      if (!model && why.unknown_mesh) {
        error(ref.pointer + "/name", "expected the name of a mesh in \"" + ref.file + "\" (" + why.message +
                                         "), found \"" + *ref.mesh_name + "\"");
        return;
      }
      if (!model) {
        error(ref.pointer + "/file", "expected a readable glTF 2.0 file, found \"" + ref.file + "\"" +
                                         (ref.resolved_path == ref.file ? "" : " (" + ref.resolved_path + ")") + ": " +
                                         why.message);
        return;
      }
      for (const std::string& w : model->warnings) warning(ref.pointer, "\"" + ref.file + "\": " + w);
      LoadedModel loaded{std::move(*model), static_cast<uint32_t>(materials_.size())};
      add_model_materials(loaded.model, ref.pointer);
      it = models_.emplace(key, std::move(loaded)).first;
    }
    const LoadedModel& loaded = it->second;
    size_t placed = 0;
    for (const MeshInstance& inst : loaded.model.instances) {
      const auto transform = make_transform(world * inst.to_file);
      if (!transform) continue;  // a node of the file scaled to nothing: it has no visible surface
      for (const ImportedPrimitive& p : loaded.model.meshes[inst.mesh]) {
        if (!take_instance(ref.pointer)) return;
        // Counted before the copy is made, so that instancing cannot exhaust memory.
        triangles_ += p.mesh.triangle_count();
        if (triangles_ > options_.limits.triangles) {
          limit_error(ref.pointer, "expected at most " + std::to_string(options_.limits.triangles) +
                                       " triangles in a scene (every instance counted), found more");
          return;
        }
        TriangleMesh mesh = transformed(p.mesh, *transform);
        for (const Vec3& v : mesh.positions) {
          if (!(max_abs_component(v) <= kMaxVertexCoordinate)) {
            error(ref.pointer, "expected \"" + ref.file +
                                   "\" within +-1.7e38 after the transforms that place it "
                                   "(half the single-precision range, so that edges stay finite), found a vertex at " +
                                   format_point(v));
            return;
          }
        }
        mesh.material = material_override ? *material_override
                        : p.material >= 0 ? loaded.first_material + static_cast<uint32_t>(p.material)
                                          : default_material();
        meshes_.push_back(std::move(mesh));
        ++placed;
      }
    }
    if (placed == 0) warning(ref.pointer, "\"" + ref.file + "\" has no triangles to render");
  }

  // The model's materials, their texture slots moved to where its textures land in the scene.
  void add_model_materials(ImportedModel& model, const std::string& pointer) {
    const auto first_texture = static_cast<uint32_t>(textures_.size());
    for (Texture& t : model.textures) {
      for (int level = 0; level < t.level_count(); ++level)
        texels_ += static_cast<uint64_t>(t.width(level)) * static_cast<uint64_t>(t.height(level));
      textures_.push_back(std::move(t));
    }
    if (texels_ > options_.limits.scene_texels)
      limit_error(pointer, "expected at most " + std::to_string(options_.limits.scene_texels) +
                               " texels in all the scene's textures together, found more");
    model.textures.clear();
    for (Material m : model.materials) {
      for (TextureSlot* slot : {&m.texture, &m.specular_texture, &m.bump.height, &m.normal_map.map})
        if (slot->present()) slot->texture += first_texture;
      materials_.push_back(m);
    }
  }

  // Our Material defaults stand in for glTF's default material (which a Phong model can't match).
  uint32_t default_material() {
    if (!default_material_) {
      default_material_ = static_cast<uint32_t>(materials_.size());
      materials_.push_back(Material{});
    }
    return *default_material_;
  }

  void limit_error(const std::string& pointer, const std::string& message) {
    over_limit_ = true;
    error(pointer, message + " (a limit that keeps memory bounded; see README, \"Limits\")");
  }
  void error(const std::string& pointer, std::string message) { report(Severity::kError, pointer, std::move(message)); }
  void warning(const std::string& pointer, std::string message) {
    report(Severity::kWarning, pointer, std::move(message));
  }
  void report(Severity severity, const std::string& pointer, std::string message) {
    if (source_) {
      const JsonReader r(*source_, diags_);
      severity == Severity::kError ? r.error(pointer, std::move(message)) : r.warning(pointer, std::move(message));
    } else {
      diags_.add(Diagnostic{severity, desc_.path, 0, 0, "", std::move(message), ""});
    }
  }

  struct LoadedModel {
    ImportedModel model;
    uint32_t first_material = 0;  // where its materials start in the scene's material list
  };

  const SceneDescription& desc_;
  const JsonDocument* source_;
  const LoadOptions& options_;
  Diagnostics& diags_;
  std::vector<Material> materials_;
  std::vector<Texture> textures_;
  std::map<std::string, uint32_t> texture_indices_;  // resolved path + encoding -> index (kNoTexture: failed)
  uint64_t texels_ = 0;                              // in textures_, mip levels included
  std::vector<AnalyticShape> shapes_;
  std::vector<TriangleMesh> meshes_;
  std::map<std::string, LoadedModel> models_;
  std::optional<uint32_t> default_material_;
  std::vector<std::string> files_;
  uint64_t instances_ = 0;
  uint64_t triangles_ = 0;
  bool over_limit_ = false;
};

}  // namespace

std::optional<Scene> build_scene(const SceneDescription& desc, const JsonDocument* source, const LoadOptions& options,
                                 Diagnostics& diags, std::vector<std::string>* files) {
  const size_t errors_before = diags.error_count();
  Builder builder(desc, source, options, diags);
  builder.add_nodes(desc.nodes, Mat4(1.0f));
  if (files) *files = builder.take_files();
  if (diags.error_count() > errors_before) return std::nullopt;
  return builder.finish();
}

}  // namespace rt
