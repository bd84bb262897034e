#pragma once
// Whether this test binary (and so the pyro it runs, built with the same flags) is instrumented
// with AddressSanitizer: such a program reserves terabytes of shadow address space at start and
// keeps freed memory in quarantine, so address-space caps and resident-memory bounds do not apply.
namespace pyro::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderAsan = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderAsan = true;
#else
inline constexpr bool kUnderAsan = false;
#endif
#else
inline constexpr bool kUnderAsan = false;
#endif

}  // namespace pyro::test
