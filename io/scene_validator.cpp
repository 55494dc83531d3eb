#include "io/scene_validator.h"

#include <algorithm>
#include <new>

#include "io/build/scene_builder.h"
#include "io/json/locate.h"
#include "io/json/reader.h"
#include "io/scene/scene_parser.h"
#include "io/scene/schema.h"
#include "io/scene_loader.h"

namespace rt {
namespace {

void validate_json_scene(const std::string& path, const LoadOptions& options, Diagnostics& diags) {
  std::optional<JsonDocument> doc = read_json_file(path, options.limits.scene_file_bytes, diags);
  if (!doc) return;
  const SceneDescription desc = parse_scene_partial(*doc, options, diags);
  build_scene(desc, &*doc, options, diags);
  const JsonReader reader(*doc, diags);
  const std::vector<Diagnostic> loader = diags.all();
  for (const SchemaError& e : check_scene_schema(doc->root)) {
    const bool reported = std::any_of(loader.begin(), loader.end(), [&](const Diagnostic& d) {
      return d.severity == Severity::kError && pointers_related(d.pointer, e.pointer);  // "" contains every pointer
    });
    if (!reported) reader.error(e.pointer, "schema: " + e.message);
  }
}

}  // namespace

Diagnostics validate_file(const std::string& path, const LoadOptions& options_in) {
  LoadOptions options = options_in;
  options.build_bvh = false;
  Diagnostics diags;
  try {
    if (is_gltf_path(path)) load_scene(path, options, diags);
    else validate_json_scene(path, options, diags);
  } catch (const std::bad_alloc&) {
    diags.file_error(path, "ran out of memory while checking: the file asks for more than this machine has");
  } catch (const std::exception& e) {
    diags.file_error(path, std::string("could not be checked: ") + e.what());
  }
  diags.sort_by_position();
  return diags;
}

}  // namespace rt
