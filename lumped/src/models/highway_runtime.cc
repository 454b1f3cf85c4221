// The three functions of Highway's runtime library that the contact kernels' dynamic dispatch
// calls (HWY_DYNAMIC_DISPATCH in contact_kernels.cc), so that no program of the toolkit loads
// libhwy.so: its static initialiser calibrates Highway's benchmark timer (TimerResolution) in
// every process that loads it (~5 % of a plain `bearing-sim run` in the profile,
// issue 31). Dispatch needs only the CPU's instruction sets, which GCC's and Clang's
// __builtin_cpu_supports give (CPUID, and XGETBV for the AVX and AVX-512 register state).
//
// The target chosen is the best one whose every instruction set the CPU has, with the sets
// Highway 1.0's targets are compiled for (hwy/ops/set_macros-inl.h, HWY_TARGET_STR_*): SSSE3 =
// sse2, ssse3; SSE4 = SSSE3 + sse4.1, sse4.2, pclmul, aes; AVX2 = SSE4 + avx, avx2, bmi, bmi2,
// fma, f16c; AVX3 = AVX2 + avx512f, avx512vl, avx512dq, avx512bw. AVX3_DL is never chosen (its
// extra sets give the kernels nothing); EMU128 and SCALAR always run. The kernels give the same
// bits on every target (test_contact_kernels.cc), so this choice changes speed only.

#if !defined(BEARING_WITHOUT_HIGHWAY)

#include <atomic>
#include <cstdint>

#include <hwy/targets.h>
#if HWY_ARCH_X86
#include <cpuid.h>
#endif

namespace {

#if HWY_ARCH_X86
// F16C from CPUID leaf 1 (ECX bit 29): Clang's __builtin_cpu_supports does not know "f16c".
bool cpu_has_f16c() {
  unsigned int eax = 0, ebx = 0, ecx = 0, edx = 0;
  return __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_F16C) != 0;
}

bool cpu_has_ssse3() {
  return __builtin_cpu_supports("sse2") && __builtin_cpu_supports("ssse3");
}
bool cpu_has_sse4() {
  return cpu_has_ssse3() && __builtin_cpu_supports("sse4.1") && __builtin_cpu_supports("sse4.2") &&
         __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("aes");
}
bool cpu_has_avx2() {
  return cpu_has_sse4() && __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") &&
         __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
         __builtin_cpu_supports("fma") && cpu_has_f16c();
}
bool cpu_has_avx3() {
  return cpu_has_avx2() && __builtin_cpu_supports("avx512f") &&
         __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512bw");
}
#endif  // HWY_ARCH_X86

int64_t detected_targets() {
  int64_t t = HWY_EMU128 | HWY_SCALAR;
#if HWY_ARCH_X86
  if (cpu_has_ssse3()) t |= HWY_SSSE3;
  if (cpu_has_sse4()) t |= HWY_SSE4;
  if (cpu_has_avx2()) t |= HWY_AVX2;
  if (cpu_has_avx3()) t |= HWY_AVX3;
#endif
  return t;
}

// The mock of SetSupportedTargetsForTest (0: none), as Highway keeps it.
std::atomic<int64_t>& targets_for_test() {
  static std::atomic<int64_t> mock{0};
  return mock;
}

}  // namespace

namespace hwy {

ChosenTarget& GetChosenTarget() {
  static ChosenTarget chosen;
  return chosen;
}

int64_t SupportedTargets() {
  int64_t targets = targets_for_test().load();
  if (targets == 0) {
    static const int64_t detected = detected_targets();
    targets = detected;
  }
  GetChosenTarget().Update(targets);
  return targets;
}

void SetSupportedTargetsForTest(int64_t targets) {
  targets_for_test().store(targets);
  GetChosenTarget().Update(SupportedTargets());
}

}  // namespace hwy

#endif  // !BEARING_WITHOUT_HIGHWAY
