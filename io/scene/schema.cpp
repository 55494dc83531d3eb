#include "io/scene/schema.h"

#include <algorithm>
#include <string_view>

#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validator.hpp>

#include "io/json/locate.h"

namespace rt {
namespace {

// The schema, parsed once per process; it is shipped with the binary, so a failure is a bug.
class SceneSchema {
 public:
  SceneSchema() {
    const Json text = Json::parse(scene_schema_text());
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    parser.populateSchema(valijson::adapters::NlohmannJsonAdapter(text), schema_);
  }
  const valijson::Schema& get() const { return schema_; }

 private:
  valijson::Schema schema_;
};

const valijson::Schema& scene_schema() {
  static const SceneSchema schema;  // immutable once built; C++ makes the first use thread-safe
  return schema.get();
}

// valijson's context {"<root>", "[materials]", "[red]", "[0]"} as "/materials/red/0".
std::string to_pointer(const std::vector<std::string>& context) {
  std::string pointer;
  for (const std::string& part : context) {
    if (part.size() >= 2 && part.front() == '[' && part.back() == ']')
      pointer = pointer_child(pointer, std::string_view(part).substr(1, part.size() - 2));
  }
  return pointer;
}

// Messages that only repeat, one level up, that something below failed.
bool is_propagation(const std::string& message) {
  for (const char* prefix :
       {"Failed to validate against schema associated with property name", "Failed to validate item #",
        "Failed to validate against child schema", "Failed to validate against additional properties schema",
        "Failed to validate against any child schemas", "Failed to validate against any schemas",
        "Failed to validate against dependent schema", "Failed to validate against items schema"})
    if (message.rfind(prefix, 0) == 0) return true;
  return false;
}

}  // namespace

std::vector<SchemaError> check_scene_schema(const Json& document) {
  valijson::Validator validator;
  valijson::ValidationResults results;
  if (validator.validate(scene_schema(), valijson::adapters::NlohmannJsonAdapter(document), &results)) return {};
  std::vector<SchemaError> all;
  for (const auto& error : results)
    if (!is_propagation(error.description)) all.push_back(SchemaError{to_pointer(error.context), error.description});
  // Where a value fails below a point (one branch of a oneOf), the deeper failure says more.
  std::vector<SchemaError> specific;
  for (const SchemaError& e : all) {
    const bool deeper_exists = std::any_of(
        all.begin(), all.end(), [&](const SchemaError& o) { return pointer_is_inside(o.pointer, e.pointer); });
    const bool repeated = std::any_of(specific.begin(), specific.end(), [&](const SchemaError& o) {
      return o.pointer == e.pointer && o.message == e.message;
    });
    if (!deeper_exists && !repeated) specific.push_back(e);
  }
  return specific;
}

}  // namespace rt
