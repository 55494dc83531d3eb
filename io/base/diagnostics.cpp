#include "io/base/diagnostics.h"

#include <algorithm>

namespace rt {

std::string format_diagnostic(const Diagnostic& d) {
  std::string out = d.file;
  if (d.line > 0) out += ":" + std::to_string(d.line) + ":" + std::to_string(d.column);
  out += d.severity == Severity::kError ? ": error: " : ": warning: ";
  if (!d.pointer.empty()) out += d.pointer + ": ";
  out += d.message;
  return out;
}

std::string format_place(const Place& p) {
  std::string out = "  in " + p.file;
  if (p.line > 0) out += ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  if (!p.pointer.empty()) out += ": " + p.pointer;
  return out;
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      out.push_back((c < 0x20 && c != '\t' && c != '\n') || c == 0x7f ? '?' : static_cast<char>(c));
      ++i;
      continue;
    }
    // A well-formed multi-byte UTF-8 sequence is kept whole; anything else is one '?' per byte.
    const size_t length = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
    bool valid = length > 0 && i + length <= text.size();
    for (size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(text[i + k]) & 0xc0) == 0x80;
    if (valid) {
      out.append(text.substr(i, length));
      i += length;
    } else {
      out.push_back('?');
      ++i;
    }
  }
  return out;
}

void Diagnostics::add(Diagnostic d) {
  d.message = printable(d.message);
  d.excerpt = printable(d.excerpt);
  d.file = printable(d.file);
  if (d.inside) {
    d.inside->file = printable(d.inside->file);
    d.inside->pointer = printable(d.inside->pointer);
    d.inside->excerpt = printable(d.inside->excerpt);
  }
  items_.push_back(std::move(d));
}

void Diagnostics::sort_by_position() {
  std::stable_sort(items_.begin(), items_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
}

bool Diagnostics::has_errors() const { return error_count() > 0; }

size_t Diagnostics::error_count() const {
  return static_cast<size_t>(
      std::count_if(items_.begin(), items_.end(), [](const Diagnostic& d) { return d.severity == Severity::kError; }));
}

}  // namespace rt
