#include "io/assemble/model_library.h"

#include <cstdio>
#include <limits>

#include "io/assemble/load_cache.h"

namespace rt {
namespace {

// Half the float range: the difference of two such coordinates (a triangle's edge) is finite.
constexpr float kMaxVertexCoordinate = std::numeric_limits<float>::max() / 2;

std::string format_point(Vec3 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%g, %g, %g]", p.x, p.y, p.z);
  return buf;
}

}  // namespace

ModelLibrary::ModelLibrary(SceneAssets& assets, TextureLibrary& textures, const LoadOptions& options, LimitUsage& usage,
                           const BvhBuildOptions& bvh_options, std::vector<std::string>& files, Reporter& report)
    : assets_(assets),
      textures_(textures),
      options_(options),
      usage_(usage),
      bvh_options_(bvh_options),
      files_(files),
      report_(report) {}

const LoadedModel* ModelLibrary::load(const MeshReference& ref) {
  const std::string key = ref.resolved_path + '\n' + ref.mesh_name.value_or("") + '\n' + ref.animation.value_or("");
  if (const auto it = models_.find(key); it != models_.end()) return it->second ? &*it->second : nullptr;
  std::optional<LoadedModel>& slot = models_[key];
  Diagnostics found;
  Reporter in_file(found, ref.resolved_path);
  ImportError why;
  // A cached import (rtcli watch) stands for a fresh one: the same model, BVHs and warnings.
  const std::string cache_key = key + '\n' + (options_.build_bvh ? isa_name(bvh_options_.isa) : "no BVH") + '\n' +
                                (options_.limits.outside_files ? "outside" : "inside");
  const LoadCache::Model* kept = options_.cache ? options_.cache->model(cache_key, usage_, options_.limits) : nullptr;
  std::optional<ImportedModel> model;
  std::optional<LoadCache::Model> keep;  // what the cache will hold of a fresh import
  if (kept) {
    model = kept->model;
    usage_.texels += kept->used.texels;
    usage_.vertices += kept->used.vertices;
    usage_.triangles += kept->used.triangles;
    usage_.animation_keys += kept->used.animation_keys;
    for (const Diagnostic& d : kept->warnings) found.add(d);
  } else {
    const LimitUsage before = usage_;
    const std::optional<FileStamp> stamp = stamp_file(ref.resolved_path);  // before reading: a later change shows
    model = import_gltf(ref.resolved_path, GltfSelection{ref.mesh_name, ref.animation}, options_.limits, usage_,
                        in_file, why);
    if (model && options_.cache && in_file.errors() == 0) {
      keep.emplace();
      keep->files = FileStamps::of(model->files);
      if (!keep->files.stamps.empty()) keep->files.stamps[0] = stamp;
      keep->model = *model;
      keep->used = LimitUsage{usage_.texels - before.texels, usage_.vertices - before.vertices,
                              usage_.triangles - before.triangles, usage_.animation_keys - before.animation_keys};
      keep->warnings = found.all();
    }
  }
  if (model) files_.insert(files_.end(), model->files.begin(), model->files.end());
  const std::string quoted = "\"" + ref.file + "\"";
  const std::string unreadable = "expected a readable glTF 2.0 file, found " + quoted +
                                 (ref.resolved_path == ref.file ? "" : " (" + ref.resolved_path + ")") + ": ";
  for (const Diagnostic& d : found.all()) {
    if (d.severity == Severity::kWarning) report_.add_inside(d, ref.pointer, quoted + ": ");
    else if (in_file.stopped_by_limit()) report_.add_inside(d, ref.pointer + "/file", quoted + ": ");
    else report_.add_inside(d, ref.pointer + "/file", unreadable);
  }
  if (in_file.stopped_by_limit()) report_.stop_for_limit();
  if (!model && why.unknown_mesh) {
    report_.error(ref.pointer + "/name", "expected the name of a mesh in " + quoted + " (" + why.message +
                                             "), found \"" + *ref.mesh_name + "\"");
    return nullptr;
  }
  if (!model && why.unknown_animation) {
    // A model on its own was asked for it by --animation; a scene file by its "animation" key.
    const std::string expected = "expected the name or index of an animation in " + quoted + " (" + why.message +
                                 "), found \"" + *ref.animation + "\"";
    if (ref.pointer.empty()) report_.error("", "--animation: " + expected);
    else report_.error(ref.pointer + "/animation", expected);
    return nullptr;
  }
  if (!model && in_file.errors() == 0) report_.error(ref.pointer + "/file", unreadable + "not a readable glTF file");
  if (!model) return nullptr;
  LoadedModel loaded;
  const auto first_material = static_cast<uint32_t>(assets_.materials.size());
  add_materials(*model);
  loaded.meshes.resize(model->meshes.size());
  size_t primitive = 0;
  for (size_t m = 0; m < model->meshes.size(); ++m) {
    for (ImportedPrimitive& p : model->meshes[m]) {
      const Bvh* built = kept && primitive < kept->bvhs.size() ? &kept->bvhs[primitive] : nullptr;
      ++primitive;
      if (!add_geometry(std::move(p.mesh), ref, built)) return nullptr;
      if (keep && options_.build_bvh) keep->bvhs.push_back(assets_.meshes.back().bvh);
      const uint32_t material =
          p.material >= 0 ? first_material + static_cast<uint32_t>(p.material) : default_material();
      loaded.meshes[m].push_back(
          LoadedPrimitive{static_cast<uint32_t>(assets_.meshes.size() - 1), material, p.material});
    }
  }
  model->meshes.clear();
  if (keep) options_.cache->keep(cache_key, std::move(*keep));
  loaded.model = std::move(*model);
  slot = std::move(loaded);
  return &*slot;
}

// The mesh in its object space with its own BVH (counted against the triangle limit once, at
// import, however often it is placed: instances share it).
bool ModelLibrary::add_geometry(TriangleMesh mesh, const MeshReference& ref, const Bvh* built) {
  for (const Vec3& v : mesh.positions) {
    if (!(max_abs_component(v) <= kMaxVertexCoordinate)) {
      report_.error(ref.pointer, "expected \"" + ref.file +
                                     "\" within +-1.7e38 (half the single-precision range, so that "
                                     "edges stay finite), found a vertex at " +
                                     format_point(v));
      return false;
    }
  }
  MeshGeometry g;
  g.mesh = std::move(mesh);
  for (const uint32_t i : g.mesh.indices) g.bounds.extend(g.mesh.positions[i]);
  if (built) g.bvh = *built;
  else if (options_.build_bvh) g.bvh = Bvh(make_triangle_set(g.mesh), bvh_options_);
  assets_.meshes.push_back(std::move(g));
  return true;
}

// The model's materials, their texture slots moved to where its textures land in the scene (the
// import counted their texels).
void ModelLibrary::add_materials(ImportedModel& model) {
  const auto first_texture = static_cast<uint32_t>(assets_.textures.size());
  for (Texture& t : model.textures) textures_.add(std::move(t));
  model.textures.clear();
  for (Material m : model.materials) {
    for (TextureSlot* slot : m.texture_slots())
      if (slot->present()) slot->texture += first_texture;
    assets_.materials.push_back(m);
  }
}

// Our Material defaults stand in for glTF's default material (which a Phong model can't match).
uint32_t ModelLibrary::default_material() {
  if (!default_material_) {
    default_material_ = static_cast<uint32_t>(assets_.materials.size());
    assets_.materials.push_back(Material{});
  }
  return *default_material_;
}

}  // namespace rt
