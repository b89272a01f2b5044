// One compiled copy of a hot loop per vector width the processor may offer (AVX-512, AVX2, the
// baseline), picked once when the library loads. Files that use it compile without floating-point
// contraction (see libbake/CMakeLists.txt), so no copy fuses a multiply into an add and every copy
// rounds alike: outputs are the same bytes on every machine.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__)
#define BAKE_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define BAKE_VECTOR_CLONES
#endif

// For the small templates a cloned function is built from: inlined, so that they compile for the
// clone's vector width.
#define BAKE_INLINE_KERNEL inline __attribute__((always_inline))
