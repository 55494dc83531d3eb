// The one way a problem travels from where it is found to the user: a Reporter names the file it
// reports about and, once that file's text is known, finds each JSON pointer's line:column and
// excerpt in it (a PlaceFinder); every error and warning becomes a Diagnostic in one collection.
// Scene files (io/json/reader.h), glTF files (io/gltf/) and the builder all report this way, so
// `render`, `validate`, `--quiet` and `--json` see every problem alike. A leaf that reads or
// writes one file (io/base/input_file.h, the image codecs in io/image/) knows no pointer: it
// returns why it failed, as a value, to the one caller that reports it here.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "io/base/diagnostics.h"

namespace rt {

// Which part of a keyed value a report points at: the value, its key, or the object holding it.
enum class Anchor { kValue, kKey, kParent };

// Where `pointer` (with `anchor`) lies in the reported file. Fills line, column and excerpt; may
// leave them 0 and empty (a binary file, a pointer that names nothing).
using PlaceFinder = std::function<void(const std::string& pointer, Anchor anchor, Place& place)>;

class Reporter {
 public:
  // Finding a place scans the file's text, so only this many problems per file get one (line,
  // column, excerpt); later ones keep their pointer. A hostile file with a warning per primitive
  // then costs time linear in its size, not quadratic.
  static constexpr size_t kPlacesPerFile = 100;

  // pointers_shown = false: the pointers name a description the user never wrote (a model
  // rendered on its own), so reports carry none.
  Reporter(Diagnostics& out, std::string file, PlaceFinder find = {}, bool pointers_shown = true)
      : out_(out), file_(std::move(file)), find_(std::move(find)), pointers_shown_(pointers_shown) {}

  // Once the file's text has been read (a glTF file's JSON): positions from then on.
  void find_places_with(PlaceFinder find) {
    find_ = std::move(find);
    last_asked_.reset();
  }

  void error(const std::string& pointer, std::string message, Anchor anchor = Anchor::kValue) {
    add(Severity::kError, pointer, std::move(message), anchor);
  }
  void warning(const std::string& pointer, std::string message, Anchor anchor = Anchor::kValue) {
    add(Severity::kWarning, pointer, std::move(message), anchor);
  }
  // An error that stops loading: the file is fine, but a limit on memory has no room for it.
  void over_limit(const std::string& pointer, const std::string& message);

  // A diagnostic made elsewhere, counted as this reporter's own.
  void add(Diagnostic d);

  // A problem found inside a file this one references at `pointer` (a glTF file a scene node
  // names), reported at that reference: `prefix` before its message, and its own place inside
  // the referenced file attached (Diagnostic::inside). Where the reference has no place to show
  // (no position, no pointer: a model rendered on its own), it keeps its own place.
  void add_inside(const Diagnostic& inner, const std::string& pointer, const std::string& prefix);
  // A limit met inside a referenced file stops this reporter's loading too.
  void stop_for_limit() { over_limit_ = true; }

  // Where a pointer is, as this reporter would report it.
  Place place(const std::string& pointer, Anchor anchor = Anchor::kValue) const;

  const std::string& file() const { return file_; }
  size_t errors() const { return errors_; }
  bool stopped_by_limit() const { return over_limit_; }
  Diagnostics& diagnostics() const { return out_; }

 private:
  void add(Severity severity, const std::string& pointer, std::string message, Anchor anchor);

  Diagnostics& out_;
  std::string file_;
  PlaceFinder find_;
  bool pointers_shown_ = true;
  size_t errors_ = 0;
  bool over_limit_ = false;
  mutable size_t places_found_ = 0;
  mutable std::optional<std::pair<std::string, Anchor>> last_asked_;  // many reports name one pointer
  mutable Place last_place_;
};

}  // namespace rt
