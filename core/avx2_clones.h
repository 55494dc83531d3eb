// RT_AVX2_CLONES before a function's definition compiles it twice, for baseline x86-64 and for
// AVX2 (GCC's target_clones: the loader picks the one this CPU runs, once); the rest of rtcli
// stays baseline (core/accel/bvh_kernels.h has the BVH's own per-ISA copies). Both give the same
// floats: IEEE either way, and no FMA (-ffp-contract=off). GCC on x86-64 only: clang and the
// sanitizers get the baseline alone (under ThreadSanitizer the loader runs the clones' resolvers
// before the sanitizer's runtime has started, and the program dies at start with a segmentation
// fault: GCC 12, a two-line program shows it). A helper the clone should inline needs
// always_inline: GCC does not inline baseline code into an AVX2 clone of its own accord.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__) && \
    !defined(__SANITIZE_THREAD__)
#define RT_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
// A third clone for x86-64-v4 (AVX-512 F, BW, CD, DQ, VL), for integer work on 64-bit lanes:
// DQ and VL multiply them in one instruction, where AVX2 builds each product from three 32-bit
// ones (core/owen_sobol_batch.cpp).
#define RT_AVX2_V4_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define RT_AVX2_CLONES
#define RT_AVX2_V4_CLONES
#endif
