#include "core/accel/isa.h"

namespace rt {

bool isa_supported(Isa isa) {
#if defined(__x86_64__)
  // libgcc's CPU model checks the CPUID bits and, for AVX and AVX-512, that the operating system
  // saves the wider registers (XGETBV).
  switch (isa) {
    case Isa::kSse: return true;
    case Isa::kAvx2: return __builtin_cpu_supports("avx2");
    case Isa::kAvx512: return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  }
  return false;
#else
  return isa == Isa::kSse;  // elsewhere the "sse" kernels are the portable build
#endif
}

Isa best_isa() {
  Isa best = Isa::kSse;
  for (Isa isa : kAllIsas)
    if (isa_supported(isa)) best = isa;
  return best;
}

std::string supported_isa_names() {
  std::string names;
  for (Isa isa : kAllIsas)
    if (isa_supported(isa)) names += (names.empty() ? "" : ", ") + std::string(isa_name(isa));
  return names;
}

}  // namespace rt
