#include "cli/common/report.h"

namespace rt {

void print_diagnostics(std::FILE* out, const Diagnostics& diags) {
  for (const Diagnostic& d : diags.all()) {
    std::fprintf(out, "%s\n", format_diagnostic(d).c_str());
    if (!d.excerpt.empty()) std::fprintf(out, "%s\n", d.excerpt.c_str());
    if (d.inside) {
      std::fprintf(out, "%s\n", format_place(*d.inside).c_str());
      if (!d.inside->excerpt.empty()) std::fprintf(out, "%s\n", d.inside->excerpt.c_str());
    }
  }
  const size_t errors = diags.error_count();
  if (errors > 1) std::fprintf(out, "%zu errors\n", errors);
}

bool fail(const std::string& message) {
  std::fprintf(stderr, "rtcli: error: %s\n", message.c_str());
  return false;
}

}  // namespace rt
