#pragma once

// RS_VECTOR_CLONES before a function with a hot vectorised loop compiles it
// twice, for AVX2 and for the x86-64 baseline (SSE2), and the loader picks
// the one the CPU runs (GCC/Clang function multi-versioning). The baseline
// build has to run on any x86-64, and AVX2 vectors hold twice the floats.
// The clones give equal results to the bit: AVX2 does not bring FMA, so no
// multiply-add gets contracted, and the loops it is used on have no
// reductions whose order the vector width would change.
#if defined(__x86_64__) && defined(__ELF__) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(__SANITIZE_ADDRESS__)
#define RS_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define RS_VECTOR_CLONES
#endif
