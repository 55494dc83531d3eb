// A glTF 2.0 file (.gltf with external or embedded buffers, or .glb) as description records:
// its default scene's node tree with each local transform kept as translation, rotation and
// scale, the meshes the nodes use, materials, textures and animation tracks. Every primitive
// in triangle, strip or fan mode is imported; points and lines are skipped with a warning.
// Positions stay in each mesh's own space, so a mesh used by several nodes is read once. Everything a file says is
// checked against the specification and the limits before it is used (io/gltf/file.h, io/gltf/accessor.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/gltf/imported_model.h"

namespace rt {

// Every node with a mesh, at rest (the tracks not applied).
std::vector<ModelPlacement> placements(const ImportedModel& model);

// With selection.mesh: that mesh only, on one node with an identity transform. Without: every mesh
// the file's default scene places, at its node transforms (or every mesh once if the file has no
// scene), and its animations: all of them, played together, or selection.animation alone.
// Vertices, triangles, texels and animation keys are checked against what `usage` says the scene
// has left of `limits` before they are read or decoded, and added to it. Every problem and
// warning goes to `report` (a reporter on the glTF file: its pointers, and a .gltf's
// line:column); one past a limit stops the import (report.stopped_by_limit()).
std::optional<ImportedModel> import_gltf(const std::string& path, const GltfSelection& selection,
                                         const LoadLimits& limits, LimitUsage& usage, Reporter& report,
                                         ImportError& error);

// The same from the file's bytes already in memory; external buffers resolve against base_dir.
std::optional<ImportedModel> import_gltf_bytes(const std::vector<unsigned char>& bytes, const std::string& base_dir,
                                               const GltfSelection& selection, const LoadLimits& limits,
                                               LimitUsage& usage, Reporter& report, ImportError& error);

}  // namespace rt
