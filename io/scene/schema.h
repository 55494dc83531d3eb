// schemas/scene.schema.json, compiled into the binary (so `rtcli validate` works wherever the
// binary goes) and checked with valijson (Debian's libvalijson-dev). valijson reports a failure at
// every level of the tree; these are reduced to the most specific ones.
#pragma once

#include <string>
#include <vector>

#include "io/json/document.h"

namespace rt {

struct SchemaError {
  std::string pointer;  // JSON pointer of the value that failed
  std::string message;  // valijson's description
};

// The schema's text, as shipped in schemas/scene.schema.json.
const std::string& scene_schema_text();

// What the schema rejects in `document`: empty when it is valid.
std::vector<SchemaError> check_scene_schema(const Json& document);

}  // namespace rt
