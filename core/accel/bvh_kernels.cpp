#include "core/accel/bvh_kernels.h"

namespace rt {

const BvhKernels& bvh_kernels(Isa isa) {
#if defined(RTCLI_X86_KERNELS)
  switch (isa) {
    case Isa::kSse: return isa_sse::kKernels;
    case Isa::kAvx2: return isa_avx2::kKernels;
    case Isa::kAvx512: return isa_avx512::kKernels;
  }
#endif
  (void)isa;  // one portable build elsewhere (isa_supported() admits only "sse" there)
  return isa_sse::kKernels;
}

}  // namespace rt
