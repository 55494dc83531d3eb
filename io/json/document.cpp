#include "io/json/document.h"

#include <set>
#include <vector>

#include "io/base/input_file.h"
#include "io/json/locate.h"

namespace rt {
namespace {

// Builds the DOM like nlohmann's own parser, and also tracks the JSON pointer of the value being
// parsed, so that a syntax error or an overflowing number can be reported with its pointer,
// and a key repeated within one object is caught instead of silently overwriting the first.
class TrackingSax {
 public:
  explicit TrackingSax(Json& root) : dom_(root, false) {}

  bool null() { return done(dom_.null()); }
  bool boolean(bool v) { return done(dom_.boolean(v)); }
  bool number_integer(Json::number_integer_t v) { return done(dom_.number_integer(v)); }
  bool number_unsigned(Json::number_unsigned_t v) { return done(dom_.number_unsigned(v)); }
  bool number_float(Json::number_float_t v, const std::string& s) { return done(dom_.number_float(v, s)); }
  bool string(std::string& v) { return done(dom_.string(v)); }
  bool binary(Json::binary_t& v) { return done(dom_.binary(v)); }
  bool start_object(std::size_t n) {
    if (too_deep()) return false;
    frames_.push_back(Frame{true, 0, {}, {}});
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    Frame& f = frames_.back();
    if (!f.keys.insert(k).second) duplicates_.push_back(pointer_child(pointer(frames_.size() - 1), k));
    f.key = k;
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return done(dom_.end_object());
  }
  bool start_array(std::size_t n) {
    if (too_deep()) return false;
    frames_.push_back(Frame{false, 0, {}, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return done(dom_.end_array());
  }
  // `position` is one past the last character read. For a syntax error that is the offending
  // character; an overflowing number has been read whole, and `last_token` is exactly its text.
  // (For other errors last_token also holds whitespace read before the token: not usable.)
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& last_token, const Exception& ex) {
    const bool overflow = ex.id == 406;
    const size_t back = overflow ? last_token.size() : 1;
    error_ = Error{position >= back ? position - back : 0, pointer(frames_.size()), ex.what(), overflow};
    return false;
  }

  struct Error {
    size_t offset = 0;
    std::string pointer;
    std::string what;
    bool overflow = false;  // a number too large for a double
  };
  const std::optional<Error>& error() const { return error_; }
  bool nesting_exceeded() const { return nesting_exceeded_; }
  static constexpr size_t kMaxNesting = kMaxJsonNesting;
  const std::vector<std::string>& duplicates() const { return duplicates_; }

 private:
  struct Frame {
    bool object;
    size_t index;     // arrays: index of the element being parsed
    std::string key;  // objects: key of the member being parsed
    std::set<std::string> keys;
  };

  bool too_deep() {
    if (frames_.size() < kMaxNesting) return false;
    nesting_exceeded_ = true;
    return true;
  }

  bool done(bool ok) {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return ok;
  }
  std::string pointer(size_t depth) const {
    std::string p;
    for (size_t i = 0; i < depth; ++i)
      p = frames_[i].object ? pointer_child(p, frames_[i].key) : pointer_child(p, frames_[i].index);
    return p;
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  std::vector<Frame> frames_;
  std::optional<Error> error_;
  std::vector<std::string> duplicates_;
  bool nesting_exceeded_ = false;
};

}  // namespace

bool json_nesting_within(std::string_view text, size_t max_depth) {
  size_t depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (const size_t end = comment_end(text, i); end != i) {
      i = end - 1;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) return false;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return true;
}

// nlohmann's messages start "[json.exception.parse_error.101] parse error at line 3, column 8: ";
// we print our own position, so keep only what follows.
std::string clean_parser_message(std::string what) {
  const size_t bracket = what.find("] ");
  if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what.erase(0, bracket + 2);
  const size_t column = what.find(", column ");
  if (what.rfind("parse error", 0) == 0 && column != std::string::npos) {
    const size_t colon = what.find(": ", column);
    if (colon != std::string::npos) what.erase(0, colon + 2);
  }
  return what;
}

namespace {

Diagnostic at_offset(const std::string& path, const std::string& text, size_t offset, std::string pointer,
                     std::string message) {
  const LineColumn lc = line_column(text, offset);
  return Diagnostic{
      Severity::kError, path, lc.line, lc.column, std::move(pointer), std::move(message), source_excerpt(text, offset),
      std::nullopt};
}

}  // namespace

std::optional<JsonDocument> read_json_file(const std::string& path, uint64_t max_bytes, Diagnostics& diags) {
  std::string error;
  std::optional<std::string> text = read_input_text(path, max_bytes, error);
  if (!text) {
    diags.file_error(path, error);
    return std::nullopt;
  }
  return parse_json_text(path, std::move(*text), diags);
}

std::optional<JsonDocument> parse_json_text(std::string path, std::string text, Diagnostics& diags) {
  if (text.rfind("glTF", 0) == 0) {
    diags.file_error(path, "expected a JSON scene, found a binary glTF file (name it .glb to render it as a model)");
    return std::nullopt;
  }
  if (text.substr(0, 4096).find('\0') != std::string::npos) {
    diags.file_error(path, "expected a JSON scene, found binary data");
    return std::nullopt;
  }
  JsonDocument doc{std::move(path), std::move(text), Json()};
  TrackingSax sax(doc.root);
  const bool ok = Json::sax_parse(doc.text, &sax, Json::input_format_t::json, true, /*ignore_comments=*/true);
  if (sax.nesting_exceeded()) {
    diags.file_error(doc.path, "expected JSON nested at most " + std::to_string(TrackingSax::kMaxNesting) +
                                   " levels deep, found deeper nesting");
    return std::nullopt;
  }
  if (!ok || sax.error()) {
    if (!sax.error()) {
      diags.file_error(doc.path, "invalid JSON");
      return std::nullopt;
    }
    const auto& e = *sax.error();
    std::string message;
    if (e.overflow) {
      const std::string token = doc.text.substr(e.offset, doc.text.find_first_of(",]} \n\r\t", e.offset) - e.offset);
      message = "expected a finite number, found " + token + " (too large for a double)";
    } else {
      message = "invalid JSON: " + clean_parser_message(e.what);
    }
    diags.add(at_offset(doc.path, doc.text, e.offset, e.pointer, message));
    return std::nullopt;
  }
  for (const std::string& pointer : sax.duplicates()) {
    const auto loc = locate_pointer(doc.text, pointer);
    diags.add(at_offset(doc.path, doc.text, loc ? loc->key_offset : 0, pointer,
                        "expected each key once per object, found this key repeated (the last value would win)"));
  }
  if (!sax.duplicates().empty()) return std::nullopt;
  return doc;
}

}  // namespace rt
