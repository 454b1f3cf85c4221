#pragma once
// BEARING_TARGET_CLONES: compile a function for x86-64-v4 (AVX-512), x86-64-v3 (AVX2) and the
// baseline, the one the processor runs chosen once when the program loads (GCC's and Clang's
// target_clones, an ifunc). For the element-wise loops of the hot path that the vectoriser widens:
// built without fused multiply-adds (-ffp-contract=off on their files), their arithmetic is the
// same lane by lane, so every clone gives the same bits. The sanitizer builds check the baseline
// alone (their runtimes and load-time resolvers do not mix), as does any other compiler or
// processor family.

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define BEARING_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define BEARING_SANITIZED 1
#endif
#endif

#if defined(__x86_64__) && defined(__GNUC__) && defined(__linux__) && !defined(BEARING_SANITIZED)
#define BEARING_TARGET_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define BEARING_TARGET_CLONES
#endif
