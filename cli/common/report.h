// Printing load diagnostics for a person at a terminal.
#pragma once

#include <cstdio>

#include "io/base/diagnostics.h"

namespace rt {

// Every diagnostic (its line, then the source excerpt; for a problem inside a referenced file,
// "  in FILE:LINE:COLUMN: POINTER" and that file's excerpt), then "N errors" when there are several.
void print_diagnostics(std::FILE* out, const Diagnostics& diags);

}  // namespace rt
