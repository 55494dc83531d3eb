// A JSON file read into memory: its text (kept for error positions) and its value tree.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/diagnostics.h"

namespace rt {

using Json = nlohmann::json;

struct JsonDocument {
  std::string path;  // as the user named it
  std::string text;
  Json root;
};

// Reads and parses a JSON file. Syntax errors, numbers that overflow a double and repeated keys
// in one object are recorded (with line:column and pointer) and give nothing back.
std::optional<JsonDocument> read_json_file(const std::string& path, Diagnostics& diags);
std::optional<JsonDocument> parse_json_text(std::string path, std::string text, Diagnostics& diags);

// A message from nlohmann::json (also inside tinygltf's errors) without its exception-id prefix
// and its own "at line L, column C" (we report positions ourselves).
std::string clean_parser_message(std::string what);

// Reads a whole file; on failure returns nothing and sets `error` to a sentence for the user.
std::optional<std::string> read_text_file(const std::string& path, std::string& error);

}  // namespace rt
