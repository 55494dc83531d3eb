// The x86-64 instruction sets rtcli's BVH traversal is compiled for, and which of them this CPU
// runs. The traversal is built once per set (core/accel/bvh_kernels.h) and one is chosen at
// start-up: the best the CPU has, or the one the user forces (rtcli --isa, RTCLI_ISA). Every set
// gives the same bits: the kernels use no fused multiply-add and no approximate instructions.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/name_table.h"

namespace rt {

enum class Isa {
  kSse,     // x86-64's baseline (SSE2): runs everywhere
  kAvx2,    // AVX2: one 8-lane instruction per slab step
  kAvx512,  // AVX-512 F and VL, kept to 256-bit vectors: more registers, mask compares
};

// "sse", "avx2", "avx512": the names --isa and RTCLI_ISA take and the render summary prints,
// narrowest first ("auto", the widest the CPU runs, is the caller's to handle).
inline constexpr NameEntry<Isa> kIsaEntries[] = {{"sse", Isa::kSse, "x86-64's baseline, runs everywhere"},
                                                 {"avx2", Isa::kAvx2, "8-lane AVX2"},
                                                 {"avx512", Isa::kAvx512, "AVX-512 F and VL, 256-bit vectors"}};
inline constexpr NameTable<Isa> kIsas{kIsaEntries};
inline constexpr Isa kAllIsas[] = {Isa::kSse, Isa::kAvx2, Isa::kAvx512};
static_assert(std::size(kAllIsas) == std::size(kIsaEntries));

inline const char* isa_name(Isa isa) { return kIsas.name(isa).data(); }  // the table's names are literals
inline std::optional<Isa> parse_isa(std::string_view name) { return kIsas.parse(name); }
// Whether this CPU (and its operating system, for the wider registers) runs the set.
bool isa_supported(Isa isa);
// The widest set this CPU runs.
Isa best_isa();
// The sets this CPU runs, by name: "sse, avx2", for error messages.
std::string supported_isa_names();

}  // namespace rt
