#include "io/scene/scene_sources.h"

#include <filesystem>
#include <set>

#include "io/base/input_file.h"
#include "io/json/locate.h"
#include "io/json/reader.h"

namespace rt {
namespace {

std::string identity(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
  return ec ? path : p.string();
}

class IncludeReader {
 public:
  // `bytes`: read so far (the scene file's).
  IncludeReader(const LoadLimits& limits, Diagnostics& diags, std::vector<std::unique_ptr<SceneSource>>& out,
                uint64_t bytes)
      : limits_(limits), diags_(diags), out_(out), bytes_(bytes) {}

  // Reads `source`'s includes (and theirs), appending them to out_ before `source` itself.
  // `chain`: the files including this one, outermost first, for the cycle message.
  // Problems with an include are reported in the file that lists it, at its entry.
  void add(std::unique_ptr<SceneSource> source, std::vector<std::string>& chain) {
    const Json& root = source->doc.root;
    const Json* list = root.is_object() && root.contains("include") ? &root["include"] : nullptr;
    if (list) {
      const JsonReader r(source->doc, diags_);
      if (!list->is_array()) {
        r.expected("/include", "an array of scene file names (paths relative to this file)", *list);
      } else {
        for (size_t i = 0; i < list->size(); ++i) include(*source, (*list)[i], pointer_child("/include", i), r, chain);
      }
    }
    out_.push_back(std::move(source));
  }

 private:
  // `at`: the entry's pointer in `from`.
  void include(const SceneSource& from, const Json& entry, const std::string& at, const JsonReader& r,
               std::vector<std::string>& chain) {
    const auto name = read_string(r, entry, at);
    if (!name) return;
    if (name->empty()) return r.expected(at, "the name of a scene file (.json)", entry);
    const std::string path = resolve_path(from.folder, *name);
    const std::string id = identity(path);
    for (size_t k = 0; k < chain.size(); ++k) {
      if (chain[k] != id) continue;
      std::string cycle;
      for (size_t j = k; j < chain.size(); ++j) cycle += std::filesystem::path(chain[j]).filename().string() + " -> ";
      return r.error(at, "expected no include cycle, found " + cycle + std::filesystem::path(id).filename().string());
    }
    if (!read_.emplace(id).second)
      return r.error(at, "expected each file included once, found \"" + *name + "\" included already");
    if (chain.size() >= static_cast<size_t>(kMaxIncludeDepth))
      return r.error(
          at, "expected includes nested at most " + std::to_string(kMaxIncludeDepth) + " deep, found deeper nesting");
    if (read_.size() > kMaxSceneFiles)
      return r.error(at, "expected at most " + std::to_string(kMaxSceneFiles) + " scene files, found more");
    Diagnostics found;
    const uint64_t left = limits_.scene_file_bytes - std::min(bytes_, limits_.scene_file_bytes);
    std::optional<JsonDocument> doc = read_json_file(path, left, found);
    if (!doc) {
      // Where the entry is, and inside the file what was wrong with it.
      for (const Diagnostic& d : found.all()) {
        Reporter& at_entry = r.reporter();
        std::string message = d.message;
        if (d.line == 0 && d.pointer.empty()) {
          message = "expected a readable scene file to include, found \"" + *name + "\": " + d.message;
          if (message.find("bytes") != std::string::npos || message.find("larger") != std::string::npos)
            message += " (all the scene's files together have " + format_bytes(limits_.scene_file_bytes) + ")";
          at_entry.error(at, message);
        } else {
          at_entry.add_inside(d, at, "\"" + *name + "\": ");
        }
      }
      return;
    }
    bytes_ += doc->text.size();
    auto source = std::make_unique<SceneSource>();
    source->folder = std::filesystem::path(path).parent_path().string();
    source->prefix = from.prefix + at;
    source->doc = std::move(*doc);
    if (!source->doc.root.is_object()) {
      r.expected(at, "an included file holding a JSON object (a scene's keys)", source->doc.root);
      return;
    }
    chain.push_back(id);
    add(std::move(source), chain);
    chain.pop_back();
  }

  const LoadLimits& limits_;
  Diagnostics& diags_;
  std::vector<std::unique_ptr<SceneSource>>& out_;
  std::set<std::string> read_;
  uint64_t bytes_;
};

}  // namespace

SceneSources::SceneSources(JsonDocument doc) {
  auto source = std::make_unique<SceneSource>();
  source->folder = std::filesystem::path(doc.path).parent_path().string();
  source->doc = std::move(doc);
  files_.push_back(std::move(source));
}

PlaceFinder SceneSources::places() const {
  return [this](const std::string& pointer, Anchor anchor, Place& place) {
    // The deepest file whose prefix the pointer starts with (whole segments).
    const SceneSource* in = nullptr;
    for (const auto& f : files_) {
      const std::string& p = f->prefix;
      const bool starts =
          pointer.compare(0, p.size(), p) == 0 && (pointer.size() == p.size() || pointer[p.size()] == '/');
      if (starts && (!in || p.size() > in->prefix.size())) in = f.get();
    }
    if (!in) return;
    const std::string inner = pointer.substr(in->prefix.size());
    place.file = in->doc.path;
    place.pointer = inner;
    json_places(in->doc)(inner, anchor, place);
  };
}

std::vector<std::string> SceneSources::paths() const {
  std::vector<std::string> out{scene().doc.path};
  for (size_t i = 0; i + 1 < files_.size(); ++i) out.push_back(files_[i]->doc.path);
  return out;
}

std::optional<SceneSources> read_scene_sources(const std::string& path, const LoadLimits& limits, Diagnostics& diags) {
  std::optional<JsonDocument> doc = read_json_file(path, limits.scene_file_bytes, diags);
  if (!doc) return std::nullopt;
  SceneSources sources;
  auto scene = std::make_unique<SceneSource>();
  scene->folder = std::filesystem::path(path).parent_path().string();
  scene->doc = std::move(*doc);
  std::vector<std::string> chain{identity(path)};
  IncludeReader reader(limits, diags, sources.files_, scene->doc.text.size());
  reader.add(std::move(scene), chain);
  return sources;
}

}  // namespace rt
