#include "cli/common/report.h"

namespace rt {

std::string diagnostic_text(const Diagnostic& d) {
  std::string text = format_diagnostic(d) + "\n";
  if (!d.excerpt.empty()) text += d.excerpt + "\n";
  if (d.inside) {
    text += format_place(*d.inside) + "\n";
    if (!d.inside->excerpt.empty()) text += d.inside->excerpt + "\n";
  }
  return text;
}

void print_diagnostics(std::FILE* out, const Diagnostics& diags) {
  for (const Diagnostic& d : diags.all()) std::fputs(diagnostic_text(d).c_str(), out);
  const size_t errors = diags.error_count();
  if (errors > 1) std::fprintf(out, "%zu errors\n", errors);
}

bool fail(const std::string& message) {
  std::fprintf(stderr, "rtcli: error: %s\n", message.c_str());
  return false;
}

}  // namespace rt
