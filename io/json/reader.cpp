#include "io/json/reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/json/locate.h"

namespace rt {

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

namespace {

std::string quote_text(std::string_view s) {
  std::string out = "\"";
  if (s.size() > 40) {
    out += s.substr(0, 37);
    out += "...";
  } else {
    out += s;
  }
  return out + "\"";
}

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string join_quoted(const std::vector<std::string>& items) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + quote_text(items[i]);
  return out;
}

namespace {

void find_in_text(std::string_view text, const std::string& pointer, Anchor anchor, Place& place) {
  const std::string where = anchor == Anchor::kParent ? pointer.substr(0, pointer.rfind('/')) : pointer;
  const auto loc = locate_pointer(text, where);
  if (!loc) return;
  const size_t offset = anchor == Anchor::kKey ? loc->key_offset : loc->value_offset;
  const LineColumn lc = line_column(text, offset);
  place.line = lc.line;
  place.column = lc.column;
  place.excerpt = source_excerpt(text, offset);
}

}  // namespace

PlaceFinder json_places(std::shared_ptr<const std::string> text) {
  return [text = std::move(text)](const std::string& pointer, Anchor anchor, Place& place) {
    find_in_text(*text, pointer, anchor, place);
  };
}

PlaceFinder json_places(const JsonDocument& doc) {
  return [&doc](const std::string& pointer, Anchor anchor, Place& place) {
    find_in_text(doc.text, pointer, anchor, place);
  };
}

void JsonReader::error(const std::string& pointer, std::string message, Anchor anchor) const {
  report_.error(pointer, std::move(message), anchor);
}

void JsonReader::warning(const std::string& pointer, std::string message, Anchor anchor) const {
  report_.warning(pointer, std::move(message), anchor);
}

void JsonReader::expected(const std::string& pointer, std::string_view what, const Json& found) const {
  error(pointer, "expected " + std::string(what) + ", found " + describe(found));
}

std::string describe(const Json& v) {
  switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return std::string("the boolean ") + (v.get<bool>() ? "true" : "false");
    case Json::value_t::string: return "the string " + quote_text(v.get<std::string>());
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned: return "the number " + v.dump();
    case Json::value_t::number_float: return "the number " + format_number(v.get<double>());
    case Json::value_t::array: {
      std::string out = "an array of " + std::to_string(v.size()) + (v.size() == 1 ? " element" : " elements");
      if (!v.empty() && v.size() <= 4 &&
          std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_primitive(); }))
        out += " " + v.dump();
      return out;
    }
    case Json::value_t::object: {
      if (v.empty()) return "an empty object";
      std::vector<std::string> keys;
      for (const auto& item : v.items()) keys.push_back(item.key());
      if (keys.size() > 4) return "an object with " + std::to_string(keys.size()) + " keys";
      return "an object with keys " + join_quoted(keys);
    }
    default: return "a binary value";
  }
}

std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::string NumberRule::describe() const {
  std::string what = integer ? "an integer" : "a number";
  const bool has_min = min != -HUGE_VAL, has_max = max != HUGE_VAL;
  if (has_min && has_max) {
    return what + " in " + (min_exclusive ? "(" : "[") + format_number(min) + ", " + format_number(max) +
           (max_exclusive ? ")" : "]");
  }
  if (has_min) return what + (min_exclusive ? " > " : " >= ") + format_number(min);
  if (has_max) return what + (max_exclusive ? " < " : " <= ") + format_number(max);
  return what;
}

bool NumberRule::accepts(double v) const {
  if (!std::isfinite(v)) return false;
  if (integer && v != std::floor(v)) return false;
  if (min_exclusive ? !(v > min) : !(v >= min)) return false;
  if (max_exclusive ? !(v < max) : !(v <= max)) return false;
  return true;
}

std::optional<double> read_number(const JsonReader& r, const Json& v, const std::string& ptr, const NumberRule& rule) {
  if (!v.is_number() || !rule.accepts(v.get<double>())) {
    r.expected(ptr, rule.describe(), v);
    return std::nullopt;
  }
  // Non-integer values are stored as floats: one that overflows would become an infinity, and
  // the range is checked again on the value as stored (1e-300 is 0 in single precision).
  const float stored = static_cast<float>(v.get<double>());
  if (!rule.integer && !std::isfinite(stored)) {
    r.expected(ptr, "a number that fits in single precision (|x| < 3.4e38)", v);
    return std::nullopt;
  }
  if (!rule.integer && !rule.accepts(stored)) {
    r.expected(ptr,
               rule.describe() + " in single precision, where it is stored (this one becomes " +
                   format_number(static_cast<double>(stored)) + ")",
               v);
    return std::nullopt;
  }
  return v.get<double>();
}

namespace {

// An array of exactly three numbers, each checked against `rule` at its own pointer.
std::optional<Vec3> read_number3(const JsonReader& r, const Json& v, const std::string& ptr, std::string_view expected,
                                 const NumberRule& rule) {
  if (!v.is_array() || v.size() != 3) {
    r.expected(ptr, expected, v);
    return std::nullopt;
  }
  Vec3 out;
  bool ok = true;
  for (size_t i = 0; i < 3; ++i) {
    const auto c = read_number(r, v[i], pointer_child(ptr, i), rule);
    ok = ok && c.has_value();
    if (c) out[static_cast<int>(i)] = static_cast<float>(*c);
  }
  if (ok && !is_finite(out)) {
    r.expected(ptr, "numbers that fit in single precision (|x| < 3.4e38)", v);
    return std::nullopt;
  }
  return ok ? std::optional<Vec3>(out) : std::nullopt;
}

}  // namespace

std::optional<Vec3> read_vec3(const JsonReader& r, const Json& v, const std::string& ptr) {
  return read_number3(r, v, ptr, kVec3Expected, kAnyNumber);
}

std::optional<Vec3> read_color(const JsonReader& r, const Json& v, const std::string& ptr) {
  if (v.is_number()) {
    const auto grey = read_number(r, v, ptr, kNonNegative);
    return grey ? std::optional<Vec3>(Vec3(static_cast<float>(*grey))) : std::nullopt;
  }
  return read_number3(r, v, ptr, kColorExpected, kNonNegative);
}

std::optional<Vec3> read_weight(const JsonReader& r, const Json& v, const std::string& ptr) {
  constexpr NumberRule kUnit{0.0, 1.0, false, false, false};
  if (v.is_number()) {
    const auto w = read_number(r, v, ptr, kUnit);
    return w ? std::optional<Vec3>(Vec3(static_cast<float>(*w))) : std::nullopt;
  }
  return read_number3(r, v, ptr, kWeightExpected, kUnit);
}

std::optional<std::string> read_string(const JsonReader& r, const Json& v, const std::string& ptr) {
  if (!v.is_string()) {
    r.expected(ptr, "a string", v);
    return std::nullopt;
  }
  return v.get<std::string>();
}

std::optional<size_t> read_choice(const JsonReader& r, const Json& v, const std::string& ptr,
                                  const std::vector<std::string>& choices) {
  if (v.is_string()) {
    const auto s = v.get<std::string>();
    for (size_t i = 0; i < choices.size(); ++i)
      if (s == choices[i]) return i;
  }
  std::string message = "expected one of " + join_quoted(choices) + ", found " + describe(v);
  if (v.is_string())
    if (const auto near = closest_match(v.get<std::string>(), choices))
      message += " (did you mean " + quote_text(*near) + "?)";
  r.error(ptr, message);
  return std::nullopt;
}

ObjectReader::ObjectReader(const JsonReader& r, const Json& value, std::string pointer)
    : r_(r), pointer_(std::move(pointer)) {
  if (value.is_object()) {
    object_ = &value;
  } else {
    r_.expected(pointer_, "an object", value);
  }
}

std::string ObjectReader::child(std::string_view key) const { return pointer_child(pointer_, key); }

bool ObjectReader::has(std::string_view key) const { return object_ && object_->contains(key); }

const Json* ObjectReader::get(std::string_view key, bool required, std::string_view expected) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  if (!object_) return nullptr;
  const auto it = object_->find(key);
  if (it == object_->end()) {
    if (required) {
      std::string message = "missing required key " + quote_text(key);
      if (!expected.empty()) message += "; expected " + std::string(expected);
      r_.error(child(key), message, Anchor::kParent);
    }
    return nullptr;
  }
  return &*it;
}

std::optional<double> ObjectReader::number(std::string_view key, const NumberRule& rule, bool required) {
  const Json* v = get(key, required, rule.describe());
  return v ? read_number(r_, *v, child(key), rule) : std::nullopt;
}

std::optional<Vec3> ObjectReader::vec3(std::string_view key, bool required) {
  const Json* v = get(key, required, kVec3Expected);
  return v ? read_vec3(r_, *v, child(key)) : std::nullopt;
}

std::optional<Vec3> ObjectReader::color(std::string_view key, bool required) {
  const Json* v = get(key, required, kColorExpected);
  return v ? read_color(r_, *v, child(key)) : std::nullopt;
}

std::optional<Vec3> ObjectReader::weight(std::string_view key, bool required) {
  const Json* v = get(key, required, kWeightExpected);
  return v ? read_weight(r_, *v, child(key)) : std::nullopt;
}

std::optional<std::string> ObjectReader::string(std::string_view key, bool required) {
  const Json* v = get(key, required, "a string");
  return v ? read_string(r_, *v, child(key)) : std::nullopt;
}

void ObjectReader::finish() {
  if (!object_) return;
  for (const auto& item : object_->items()) {
    if (std::find(known_.begin(), known_.end(), item.key()) != known_.end()) continue;
    std::string message = "unknown key " + quote_text(item.key());
    if (const auto near = closest_match(item.key(), known_)) message += " (did you mean " + quote_text(*near) + "?)";
    message += "; expected one of " + join_quoted(known_);
    r_.error(child(item.key()), message, Anchor::kKey);
  }
}

}  // namespace rt
