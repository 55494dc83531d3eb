// A scene file and the scene files it includes: "include": ["materials.json", ...] at the top
// level of any of them, paths relative to the including file. Each file is read once (a file
// included twice, or a cycle, is an error at the "include" entry); all of them together are at
// most LoadLimits::scene_file_bytes, at most kMaxIncludeDepth deep and kMaxSceneFiles in all.
//
// One reader reports on all of them: a value of an included file has the pointer
// "/include/<i>" + its pointer in that file (nested includes add another "/include/<j>"), and
// places() finds such a pointer in that file, naming the file and the pointer inside it. So the
// parser and the builder, which know one pointer per record, report problems in included files
// at their own file:line:column.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/base/diagnostics.h"
#include "io/base/load_options.h"
#include "io/base/reporter.h"
#include "io/json/document.h"

namespace rt {

inline constexpr int kMaxIncludeDepth = 16;
inline constexpr size_t kMaxSceneFiles = 256;

struct SceneSource {
  JsonDocument doc;
  std::string prefix;  // of its values' pointers: "" for the scene file, "/include/0", "/include/0/include/2", ...
  std::string folder;  // its relative paths resolve against it
};

class SceneSources {
 public:
  // The scene file alone, its includes not read (a parser test, a fuzzer).
  explicit SceneSources(JsonDocument doc);
  SceneSources(SceneSources&&) = default;

  // Included files before the file that includes them, in the order listed; the scene file last.
  // Where the same key is given twice, the later file's value wins.
  const std::vector<std::unique_ptr<SceneSource>>& files() const { return files_; }
  const SceneSource& scene() const { return *files_.back(); }
  // Where a pointer lies: the file it is in, the pointer inside it, line:column and excerpt.
  // The sources must outlive the finder.
  PlaceFinder places() const;
  // Every file read, the scene file first.
  std::vector<std::string> paths() const;

 private:
  friend std::optional<SceneSources> read_scene_sources(const std::string&, const LoadLimits&, Diagnostics&);
  SceneSources() = default;
  std::vector<std::unique_ptr<SceneSource>> files_;
};

// Reads the scene file and, recursively, what it includes. Nothing if the scene file itself
// cannot be read or parsed; a broken include is reported at its entry and left out.
std::optional<SceneSources> read_scene_sources(const std::string& path, const LoadLimits& limits, Diagnostics& diags);

}  // namespace rt
