// Which instruction set's BVH kernels a command uses (core/accel/isa.h): --isa when given, else the
// environment variable RTCLI_ISA, else the best this CPU runs. "auto" asks for the best.
#pragma once

#include <optional>
#include <string>

#include "core/accel/isa.h"

namespace rt {

// The set to use; nothing (after printing why, prefixed with `program`) for a name that is not
// sse, avx2, avx512 or auto, or for a set this CPU does not run.
std::optional<Isa> choose_isa(const std::optional<std::string>& flag, const char* program);

}  // namespace rt
