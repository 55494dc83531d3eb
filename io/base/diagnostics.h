// Load errors and warnings as values. Loaders record every problem they find and carry on
// where they can; the caller decides what to do once loading is over (pbrt collects, then
// stops). Each record says where (file, line:column, JSON pointer) and what (expected / found).
// Loaders write them through a Reporter (io/base/reporter.h), the one way problems travel.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

enum class Severity { kError, kWarning };

// A place in a file: line:column (0 when unknown, as in a binary .glb), the JSON pointer of the
// value, and the source line with a caret.
struct Place {
  std::string file;
  size_t line = 0;
  size_t column = 0;
  std::string pointer;
  std::string excerpt;
};

struct Diagnostic {
  Severity severity = Severity::kError;
  std::string file;     // as the user named it
  size_t line = 0;      // 1-based; 0 when unknown
  size_t column = 0;    // 1-based, in characters
  std::string pointer;  // JSON pointer (RFC 6901) of the value concerned; empty when none
  std::string message;  // what was expected and what was found
  std::string excerpt;  // the source line and a caret under the column; may be empty
  // For a problem inside a file that this one references (an accessor of a glTF file a scene
  // node places): where in that file. The fields above then name the reference.
  std::optional<Place> inside;
};

// "file:line:column: error: /pointer: message" — the one line a user reads first.
std::string format_diagnostic(const Diagnostic& d);
// "  in file:line:column: /pointer" — where inside the referenced file (Diagnostic::inside).
std::string format_place(const Place& p);

// Text safe to print on a terminal: control characters (but tab and newline) and bytes that are
// not valid UTF-8 become '?'. Messages quote user files, which may be anything.
std::string printable(std::string_view text);

class Diagnostics {
 public:
  void add(Diagnostic d);
  // For problems with no position inside a file (the file is missing, unreadable, ...).
  void file_error(const std::string& file, std::string message) {
    add(Diagnostic{Severity::kError, file, 0, 0, "", std::move(message), "", std::nullopt});
  }

  // In order of position in the file (for the diagnostics of one file): file-level problems (no
  // line) first, then by line:column; equal positions keep their order.
  void sort_by_position();

  bool has_errors() const;
  size_t error_count() const;
  const std::vector<Diagnostic>& all() const { return items_; }

 private:
  std::vector<Diagnostic> items_;
};

}  // namespace rt
