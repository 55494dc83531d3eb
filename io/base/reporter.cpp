#include "io/base/reporter.h"

namespace rt {

Place Reporter::place(const std::string& pointer, Anchor anchor) const {
  if (last_asked_ && last_asked_->first == pointer && last_asked_->second == anchor) return last_place_;
  Place p{file_, 0, 0, pointers_shown_ ? pointer : "", ""};
  if (find_ && pointers_shown_ && places_found_ < kPlacesPerFile) {
    ++places_found_;
    find_(pointer, anchor, p);
  }
  last_asked_ = std::make_pair(pointer, anchor);
  last_place_ = p;
  return p;
}

void Reporter::add(Severity severity, const std::string& pointer, std::string message, Anchor anchor) {
  const Place p = place(pointer, anchor);
  add(Diagnostic{severity, p.file, p.line, p.column, p.pointer, std::move(message), p.excerpt, std::nullopt});
}

void Reporter::add(Diagnostic d) {
  if (d.severity == Severity::kError) ++errors_;
  out_.add(std::move(d));
}

void Reporter::over_limit(const std::string& pointer, const std::string& message) {
  over_limit_ = true;
  error(pointer, message + " (a limit that keeps memory bounded; see docs/errors-and-limits.md, \"Limits\")");
}

void Reporter::add_inside(const Diagnostic& d, const std::string& pointer, const std::string& prefix) {
  const Place at = place(pointer);
  if (at.line == 0 && at.pointer.empty()) {
    Diagnostic out = d;
    out.message = prefix + d.message;
    add(std::move(out));
    return;
  }
  Diagnostic out{d.severity, at.file, at.line, at.column, at.pointer, prefix + d.message, at.excerpt, std::nullopt};
  // The innermost place: a problem reported through two references keeps the deepest one. A
  // problem with the file as a whole (not found, unreadable) has no place inside it to show.
  if (d.inside) out.inside = d.inside;
  else if (d.line > 0 || !d.pointer.empty()) out.inside = Place{d.file, d.line, d.column, d.pointer, d.excerpt};
  add(std::move(out));
}

}  // namespace rt
