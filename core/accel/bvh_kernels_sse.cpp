// The BVH kernels built for x86-64's baseline (no extra flags).
#define RTCLI_ISA_KERNEL
#define RTCLI_ISA_NS isa_sse
#define RTCLI_ISA Isa::kSse
#include "core/accel/bvh_kernels_impl.h"
