// The x86-64 instruction sets rtcli's BVH traversal is compiled for, and which of them this CPU
// runs. The traversal is built once per set (core/accel/bvh_kernels.h) and one is chosen at
// start-up: the best the CPU has, or the one the user forces (rtcli --isa, RTCLI_ISA). Every set
// gives the same bits: the kernels use no fused multiply-add and no approximate instructions.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace rt {

enum class Isa {
  kSse,     // x86-64's baseline (SSE2): runs everywhere
  kAvx2,    // AVX2: one 8-lane instruction per slab step
  kAvx512,  // AVX-512 F and VL, kept to 256-bit vectors: more registers, mask compares
};

inline constexpr Isa kAllIsas[] = {Isa::kSse, Isa::kAvx2, Isa::kAvx512};

// "sse", "avx2", "avx512": the names --isa and RTCLI_ISA take and the render summary prints.
const char* isa_name(Isa isa);
// The set a name means; nothing for an unknown name ("auto" is the caller's to handle).
std::optional<Isa> parse_isa(std::string_view name);
// Whether this CPU (and its operating system, for the wider registers) runs the set.
bool isa_supported(Isa isa);
// The widest set this CPU runs.
Isa best_isa();
// The sets this CPU runs, by name: "sse, avx2", for error messages.
std::string supported_isa_names();

}  // namespace rt
