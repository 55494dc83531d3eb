#include "io/json/locate.h"

#include <cctype>
#include <cstdint>

namespace rt {

size_t comment_end(std::string_view text, size_t i) {
  if (i + 1 >= text.size() || text[i] != '/') return i;
  if (text[i + 1] == '/') {
    const size_t newline = text.find('\n', i + 2);
    return newline == std::string_view::npos ? text.size() : newline + 1;
  }
  if (text[i + 1] == '*') {
    const size_t close = text.find("*/", i + 2);
    return close == std::string_view::npos ? text.size() : close + 2;
  }
  return i;
}

namespace {

// A forward scanner over well-formed JSON. Every function returns the offset just past what it
// skipped; malformed input simply ends the scan (locate then finds nothing).
class Scanner {
 public:
  explicit Scanner(std::string_view text) : s_(text) {}

  // Whitespace and comments (`// to the end of the line`, `/* ... */`), as the parser skips them.
  size_t ws(size_t i) const {
    for (;;) {
      while (i < s_.size() && (s_[i] == ' ' || s_[i] == '\t' || s_[i] == '\n' || s_[i] == '\r')) ++i;
      const size_t end = comment_end(s_, i);
      if (end == i) return i;
      i = end;
    }
  }

  // Reads the string starting at s_[i] == '"' into `out` (decoded), returns the offset after it.
  size_t string(size_t i, std::string* out) const {
    ++i;
    while (i < s_.size() && s_[i] != '"') {
      if (s_[i] != '\\') {
        if (out) out->push_back(s_[i]);
        ++i;
        continue;
      }
      if (++i >= s_.size()) break;
      const char e = s_[i++];
      if (e == 'u') {
        uint32_t cp = hex4(i);
        i += 4;
        if (cp >= 0xD800 && cp < 0xDC00 && i + 6 <= s_.size() && s_[i] == '\\' && s_[i + 1] == 'u') {
          cp = 0x10000 + ((cp - 0xD800) << 10) + (hex4(i + 2) - 0xDC00);
          i += 6;
        }
        if (out) append_utf8(*out, cp);
      } else if (out) {
        const char* map = "b\bf\fn\nr\rt\t";
        char c = e;
        for (int k = 0; map[k]; k += 2)
          if (map[k] == e) c = map[k + 1];
        out->push_back(c);
      }
    }
    return i + 1;
  }

  size_t value(size_t i) const {
    i = ws(i);
    if (i >= s_.size()) return i;
    const char c = s_[i];
    if (c == '"') return string(i, nullptr);
    if (c == '{' || c == '[') {
      const char close = c == '{' ? '}' : ']';
      i = ws(i + 1);
      if (i < s_.size() && s_[i] == close) return i + 1;
      while (i < s_.size()) {
        if (c == '{') {
          i = ws(string(ws(i), nullptr));
          ++i;  // ':'
        }
        i = ws(value(i));
        if (i >= s_.size() || s_[i] != ',') break;
        ++i;
      }
      return i + 1;
    }
    while (i < s_.size() &&
           (std::isalnum(static_cast<unsigned char>(s_[i])) || s_[i] == '-' || s_[i] == '+' || s_[i] == '.'))
      ++i;
    return i;
  }

  std::string_view text() const { return s_; }

 private:
  uint32_t hex4(size_t i) const {
    uint32_t v = 0;
    for (size_t k = i; k < i + 4 && k < s_.size(); ++k) {
      const char h = s_[k];
      v = v * 16 +
          static_cast<uint32_t>(std::isdigit(static_cast<unsigned char>(h)) ? h - '0' : (std::tolower(h) - 'a' + 10));
    }
    return v;
  }
  static void append_utf8(std::string& out, uint32_t cp) {
    if (cp < 0x80) {
      out.push_back(static_cast<char>(cp));
    } else if (cp < 0x800) {
      out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
      out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else if (cp < 0x10000) {
      out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
      out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    } else {
      out.push_back(static_cast<char>(0xF0 | (cp >> 18)));
      out.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
      out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
    }
  }

  std::string_view s_;
};

std::string escape_token(std::string_view key) {
  std::string out;
  for (const char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out.push_back(c);
  }
  return out;
}

}  // namespace

std::string pointer_child(const std::string& pointer, std::string_view key) {
  return pointer + "/" + escape_token(key);
}
std::string pointer_child(const std::string& pointer, size_t index) { return pointer + "/" + std::to_string(index); }

bool pointer_is_inside(std::string_view pointer, std::string_view ancestor) {
  return pointer.size() > ancestor.size() && pointer.substr(0, ancestor.size()) == ancestor &&
         pointer[ancestor.size()] == '/';
}

std::vector<std::string> pointer_tokens(std::string_view pointer) {
  std::vector<std::string> tokens;
  size_t i = 0;
  while (i < pointer.size() && pointer[i] == '/') {
    const size_t end = std::min(pointer.find('/', i + 1), pointer.size());
    std::string token;
    for (size_t k = i + 1; k < end; ++k) {
      if (pointer[k] == '~' && k + 1 < end) {
        token.push_back(pointer[k + 1] == '1' ? '/' : '~');
        ++k;
      } else {
        token.push_back(pointer[k]);
      }
    }
    tokens.push_back(std::move(token));
    i = end;
  }
  return tokens;
}

std::optional<JsonLocation> locate_pointer(std::string_view text, std::string_view pointer) {
  const Scanner scan(text);
  JsonLocation loc;
  loc.value_offset = loc.key_offset = scan.ws(0);
  for (const std::string& token : pointer_tokens(pointer)) {
    size_t i = loc.value_offset;
    if (i >= text.size()) return std::nullopt;
    if (text[i] == '{') {
      std::optional<JsonLocation> found;
      i = scan.ws(i + 1);
      while (i < text.size() && text[i] == '"') {
        std::string key;
        const size_t key_at = i;
        i = scan.ws(scan.string(i, &key));
        if (i >= text.size() || text[i] != ':') return std::nullopt;
        const size_t value_at = scan.ws(i + 1);
        if (key == token) found = JsonLocation{value_at, key_at};  // keep looking: the last one wins
        i = scan.ws(scan.value(value_at));
        if (i >= text.size() || text[i] != ',') break;
        i = scan.ws(i + 1);
      }
      if (!found) return std::nullopt;
      loc = *found;
    } else if (text[i] == '[') {
      if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
      const size_t wanted = std::stoul(token);
      i = scan.ws(i + 1);
      for (size_t k = 0; k < wanted; ++k) {
        i = scan.ws(scan.value(i));
        if (i >= text.size() || text[i] != ',') return std::nullopt;
        i = scan.ws(i + 1);
      }
      if (i >= text.size() || text[i] == ']') return std::nullopt;
      loc = JsonLocation{i, i};
    } else {
      return std::nullopt;
    }
  }
  return loc;
}

LineColumn line_column(std::string_view text, size_t offset) {
  LineColumn lc;
  offset = std::min(offset, text.size());
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++lc.line;
      lc.column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++lc.column;
    }
  }
  return lc;
}

std::string source_excerpt(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line_start = 0;
  if (offset > 0) {
    const size_t newline = text.rfind('\n', offset - 1);
    line_start = newline == std::string_view::npos ? 0 : newline + 1;
  }
  size_t line_end = text.find('\n', offset);
  if (line_end == std::string_view::npos) line_end = text.size();
  if (line_end > line_start && text[line_end - 1] == '\r') --line_end;
  constexpr size_t kWindow = 60;  // characters shown each side of the caret on long lines
  size_t from = line_start, to = line_end;
  std::string prefix, suffix;
  if (offset - from > kWindow) {
    from = offset - kWindow;
    prefix = "...";
  }
  if (to - offset > kWindow) {
    to = offset + kWindow;
    suffix = "...";
  }
  std::string line = prefix + std::string(text.substr(from, to - from)) + suffix;
  std::string caret = prefix.empty() ? "" : "   ";
  for (size_t i = from; i < offset; ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;
    caret.push_back(text[i] == '\t' ? '\t' : ' ');
  }
  return "    " + line + "\n    " + caret + "^";
}

}  // namespace rt
