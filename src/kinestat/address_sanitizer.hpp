// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Whether this translation unit is built with AddressSanitizer (gcc defines __SANITIZE_ADDRESS__,
// clang answers __has_feature). Code that depends on how memory is mapped or freed asks this:
// the sanitiser reserves terabytes of address space and keeps freed blocks in quarantine.

namespace kinestat {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kBuiltWithAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kBuiltWithAddressSanitizer = true;
#else
inline constexpr bool kBuiltWithAddressSanitizer = false;
#endif
#else
inline constexpr bool kBuiltWithAddressSanitizer = false;
#endif

}  // namespace kinestat
