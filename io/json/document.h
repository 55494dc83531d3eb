// A JSON file read into memory: its text (kept for error positions) and its value tree.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/base/diagnostics.h"

namespace rt {

using Json = nlohmann::json;

struct JsonDocument {
  std::string path;  // as the user named it
  std::string text;
  Json root;
};

// Reads (a regular file of at most max_bytes, io/base/input_file.h) and parses a JSON file. Syntax
// errors, numbers that overflow a double and repeated keys in one object are recorded (with
// line:column and pointer) and give nothing back.
std::optional<JsonDocument> read_json_file(const std::string& path, uint64_t max_bytes, Diagnostics& diags);
std::optional<JsonDocument> parse_json_text(std::string path, std::string text, Diagnostics& diags);

// JSON nested deeper than this is refused: scenes and glTF files are a few levels deep, and the
// limit keeps every recursive walk of a parsed tree (ours, nlohmann's, tinygltf's) far from the
// stack limit.
inline constexpr size_t kMaxJsonNesting = 512;

// Whether no array or object in `text` is nested deeper than max_depth (a scan that skips
// strings and comments; it does not check the syntax).
bool json_nesting_within(std::string_view text, size_t max_depth);

// A message from nlohmann::json (also inside tinygltf's errors) without its exception-id prefix
// and its own "at line L, column C" (we report positions ourselves).
std::string clean_parser_message(std::string what);

}  // namespace rt
