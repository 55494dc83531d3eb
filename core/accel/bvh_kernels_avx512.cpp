// The BVH kernels built for AVX512 (flags in core/CMakeLists.txt).
#define RTCLI_ISA_KERNEL
#define RTCLI_ISA_NS isa_avx512
#define RTCLI_ISA Isa::kAvx512
#include "core/accel/bvh_kernels_impl.h"
