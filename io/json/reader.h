// Typed reading of a JSON document with error collection. Every read names the JSON pointer of
// the value; a wrong value records "expected X, found Y" at its line:column and reading goes on,
// so one run reports every problem in a file. Unknown keys are errors, with a suggestion.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/math.h"
#include "core/name_table.h"
#include "io/base/diagnostics.h"
#include "io/base/reporter.h"
#include "io/json/document.h"

namespace rt {

// Where a pointer lies in JSON source text: line:column and the excerpt with its caret. The text
// is kept by the finder (shared, not copied per report).
PlaceFinder json_places(std::shared_ptr<const std::string> text);
// The same for a document that outlives the finder.
PlaceFinder json_places(const JsonDocument& doc);

class JsonReader {
 public:
  JsonReader(const JsonDocument& doc, Diagnostics& diags) : doc_(doc), report_(diags, doc.path, json_places(doc)) {}
  // Reports placed by `places` instead (a scene and its included files: io/scene/scene_sources.h).
  JsonReader(const JsonDocument& doc, Diagnostics& diags, PlaceFinder places)
      : doc_(doc), report_(diags, doc.path, std::move(places)) {}

  void error(const std::string& pointer, std::string message, Anchor anchor = Anchor::kValue) const;
  void warning(const std::string& pointer, std::string message, Anchor anchor = Anchor::kValue) const;
  // "expected <what>, found <description of value>"
  void expected(const std::string& pointer, std::string_view what, const Json& found) const;

  const JsonDocument& document() const { return doc_; }
  Diagnostics& diagnostics() const { return report_.diagnostics(); }
  // The reporter behind error() and warning(), for code that reports on the same file.
  Reporter& reporter() const { return report_; }

 private:
  const JsonDocument& doc_;
  mutable Reporter report_;  // reading is const; reporting a problem is not the document's state
};

// A short description of a value for "found ..." messages: the string "red", the number -3, ...
std::string describe(const Json& value);

// The closest of `candidates` to `word` by edit distance, if close enough to be a likely typo.
std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates);

// A number as messages show it: up to 9 significant digits, enough to tell floats apart.
std::string format_number(double v);

// Allowed range of a number; describe() says it in words for error messages.
struct NumberRule {
  double min = -HUGE_VAL;
  double max = HUGE_VAL;
  bool min_exclusive = false;
  bool max_exclusive = false;
  bool integer = false;

  std::string describe() const;
  bool accepts(double v) const;
};

inline constexpr NumberRule kAnyNumber{};
inline constexpr NumberRule kPositive{0.0, HUGE_VAL, true, false, false};
inline constexpr NumberRule kNonNegative{0.0, HUGE_VAL, false, false, false};

std::optional<double> read_number(const JsonReader& r, const Json& v, const std::string& ptr, const NumberRule& rule);
std::optional<Vec3> read_vec3(const JsonReader& r, const Json& v, const std::string& ptr);
// A colour: [r, g, b] or one number for grey; components finite and >= 0 (linear RGB).
std::optional<Vec3> read_color(const JsonReader& r, const Json& v, const std::string& ptr);
// A weight: [r, g, b] or one number, components in [0, 1].
std::optional<Vec3> read_weight(const JsonReader& r, const Json& v, const std::string& ptr);
std::optional<std::string> read_string(const JsonReader& r, const Json& v, const std::string& ptr);
// "a", "b", "c": names as error messages list them.
std::string join_quoted(const std::vector<std::string>& items);
// Index of v in `choices`; otherwise an error listing them all.
std::optional<size_t> read_choice(const JsonReader& r, const Json& v, const std::string& ptr,
                                  const std::vector<std::string>& choices);
// The same for a name table's names: the value chosen.
template <class T>
std::optional<T> read_choice(const JsonReader& r, const Json& v, const std::string& ptr, const NameTable<T>& table) {
  const std::optional<size_t> k = read_choice(r, v, ptr, table.names());
  return k ? std::optional<T>(table.entries()[*k].value) : std::nullopt;
}

inline constexpr std::string_view kVec3Expected = "an array of 3 numbers [x, y, z]";
inline constexpr std::string_view kColorExpected = "a colour: [r, g, b] with components >= 0, or one number for grey";
inline constexpr std::string_view kWeightExpected = "a weight: [r, g, b] with components in [0, 1], or one number";

// One JSON object. get() marks keys as known; finish() reports every key that was never asked for.
class ObjectReader {
 public:
  ObjectReader(const JsonReader& r, const Json& value, std::string pointer);

  bool valid() const { return object_ != nullptr; }
  const std::string& pointer() const { return pointer_; }
  std::string child(std::string_view key) const;
  bool has(std::string_view key) const;

  // The member, or nullptr when absent (recording a "missing" error if `required`).
  const Json* get(std::string_view key, bool required = false, std::string_view expected = {});

  std::optional<double> number(std::string_view key, const NumberRule& rule = kAnyNumber, bool required = false);
  std::optional<Vec3> vec3(std::string_view key, bool required = false);
  std::optional<Vec3> color(std::string_view key, bool required = false);
  std::optional<Vec3> weight(std::string_view key, bool required = false);
  std::optional<std::string> string(std::string_view key, bool required = false);

  // Records an error for every key not asked about through get() and friends.
  void finish();

 private:
  const JsonReader& r_;
  const Json* object_ = nullptr;
  std::string pointer_;
  std::vector<std::string> known_;
};

}  // namespace rt
