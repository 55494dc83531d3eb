#include "cli/common/validate_command.h"

#include <cstdio>

#include "cli/common/exit_codes.h"
#include "cli/common/report.h"
#include "cli/common/scene_loading.h"
#include "io/json/document.h"
#include "io/scene_validator.h"

namespace rt {
namespace {

Json place_json(const std::string& file, size_t line, size_t column, const std::string& pointer) {
  return Json{{"file", file},
              {"line", line ? Json(line) : Json(nullptr)},
              {"column", column ? Json(column) : Json(nullptr)},
              {"pointer", pointer}};
}

Json to_json(const Diagnostic& d) {
  Json out = place_json(d.file, d.line, d.column, d.pointer);
  out["severity"] = d.severity == Severity::kError ? "error" : "warning";
  out["message"] = d.message;
  // A problem inside a referenced file (a glTF file's accessor): where in that file.
  if (d.inside) out["inside"] = place_json(d.inside->file, d.inside->line, d.inside->column, d.inside->pointer);
  return out;
}

}  // namespace

int run_validate(const ValidateCommand& cmd) {
  bool all_valid = true;
  Json list = Json::array();
  for (const std::string& file : cmd.files) {
    const Diagnostics diags = validate_file(file, cli_load_options(0, std::nullopt, cmd.allow_outside_files));
    all_valid = all_valid && !diags.has_errors();
    if (cmd.json) {
      for (const Diagnostic& d : diags.all()) list.push_back(to_json(d));
      continue;
    }
    print_diagnostics(stderr, diags);
    if (!diags.has_errors()) std::printf("%s: valid\n", printable(file).c_str());
  }
  if (cmd.json) std::printf("%s\n", list.dump(2, ' ', false, Json::error_handler_t::replace).c_str());
  return all_valid ? kExitSuccess : kExitBadInput;
}

}  // namespace rt
