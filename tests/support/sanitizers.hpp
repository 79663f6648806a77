#pragma once
// The sanitizer tree (build-asan/: AddressSanitizer + UBSan, the tests' own
// code at -O0) runs every test at 5 to 40 times its cost in build/. There the
// heaviest reference tests sample fewer points and the property tests run
// fewer cases (support/rapidcheck_seed.cpp): memory errors and undefined
// behaviour show on the same code paths, and the accuracy each test claims
// is measured in full in build/ (docs/development.md).

namespace casteljau::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderSanitizers = true;
#else
inline constexpr bool kUnderSanitizers = false;
#endif

/// `full` in build/, `sanitized` (fewer) under the sanitizers.
constexpr int sample_count(int full, int sanitized) { return kUnderSanitizers ? sanitized : full; }

}  // namespace casteljau::test
