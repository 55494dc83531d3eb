// Printing load diagnostics for a person at a terminal.
#pragma once

#include <cstdio>
#include <string>

#include "io/base/diagnostics.h"

namespace rt {

// Every diagnostic (its line, then the source excerpt; for a problem inside a referenced file,
// "  in FILE:LINE:COLUMN: POINTER" and that file's excerpt), then "N errors" when there are several.
void print_diagnostics(std::FILE* out, const Diagnostics& diags);
// One diagnostic as print_diagnostics prints it, lines ending in newlines.
std::string diagnostic_text(const Diagnostic& d);

// Prints "rtcli: error: MESSAGE" and returns false: how a command's check refuses what it was asked.
bool fail(const std::string& message);

}  // namespace rt
