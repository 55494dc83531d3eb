// The BVH kernels built for AVX2 (flags in core/CMakeLists.txt).
#define RTCLI_ISA_KERNEL
#define RTCLI_ISA_NS isa_avx2
#define RTCLI_ISA Isa::kAvx2
#include "core/accel/bvh_kernels_impl.h"
