// Finding things in JSON source text, only when an error needs them (Tungsten's lazy approach):
// the parsed value tree carries no positions, so on an error we scan the text again for the
// value a JSON pointer names and turn its byte offset into line:column and an excerpt.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

// RFC 6901 pointers: "/materials/red/kd". Tokens are escaped ~ -> ~0, / -> ~1.
std::string pointer_child(const std::string& pointer, std::string_view key);
std::string pointer_child(const std::string& pointer, size_t index);
std::vector<std::string> pointer_tokens(std::string_view pointer);
// Whether `pointer` names a value strictly inside the one `ancestor` names ("/a/b" is inside "/a").
bool pointer_is_inside(std::string_view pointer, std::string_view ancestor);
// The same value, or one inside the other: two reports about the same part of a document.
inline bool pointers_related(std::string_view a, std::string_view b) {
  return a == b || pointer_is_inside(a, b) || pointer_is_inside(b, a);
}

struct JsonLocation {
  size_t value_offset = 0;  // first byte of the value
  size_t key_offset = 0;    // first byte of its key (the opening quote), or value_offset in arrays
};

// Where the value named by `pointer` starts in `text` (well-formed JSON). When an object repeats
// a key, the last one counts, as for the parser. Nothing if the pointer names no value.
std::optional<JsonLocation> locate_pointer(std::string_view text, std::string_view pointer);

// Scene files may hold comments, `// to the end of the line` and `/* ... */` (the parser skips
// them): the offset just past the comment starting at text[i], or i when none starts there. An
// unclosed `/*` runs to the end of the text.
size_t comment_end(std::string_view text, size_t i);

struct LineColumn {
  size_t line = 1;    // 1-based
  size_t column = 1;  // 1-based, counting UTF-8 characters
};
LineColumn line_column(std::string_view text, size_t offset);

// The line holding `offset` and a caret under it; long lines (minified files) are cut to a
// window around the offset.
std::string source_excerpt(std::string_view text, size_t offset);

}  // namespace rt
