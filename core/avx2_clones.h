// RT_AVX2_CLONES before a function's definition compiles it twice, for baseline x86-64 and for
// AVX2 (GCC's target_clones: the loader picks the one this CPU runs, once); the rest of rtcli
// stays baseline (core/accel/bvh_kernels.h has the BVH's own per-ISA copies). Both give the same
// floats: IEEE either way, and no FMA (-ffp-contract=off). GCC on x86-64 only: clang and the
// sanitizers get the baseline alone. A helper the clone should inline needs always_inline: GCC
// does not inline baseline code into an AVX2 clone of its own accord.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define RT_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define RT_AVX2_CLONES
#endif
