#include "cli/common/isa_choice.h"

#include <cstdio>
#include <cstdlib>

namespace rt {

std::optional<Isa> choose_isa(const std::optional<std::string>& flag, const char* program) {
  const char* env = std::getenv("RTCLI_ISA");
  const std::string source = flag ? "--isa " + *flag : env && *env ? "RTCLI_ISA=" + std::string(env) : "";
  const std::string name = flag ? *flag : env ? env : "";
  if (name.empty() || name == "auto") return best_isa();
  const std::optional<Isa> isa = parse_isa(name);
  if (!isa) {
    std::fprintf(stderr, "%s: error: %s: expected %s or auto\n", program, source.c_str(), kIsas.list().c_str());
    return std::nullopt;
  }
  if (!isa_supported(*isa)) {
    std::fprintf(stderr, "%s: error: %s: this CPU does not run %s (it runs %s)\n", program, source.c_str(),
                 isa_name(*isa), supported_isa_names().c_str());
    return std::nullopt;
  }
  return isa;
}

}  // namespace rt
