#pragma once
// MGP_ADDRESS_SANITIZER is 1 in a build instrumented by AddressSanitizer, else 0. GCC says so with
// __SANITIZE_ADDRESS__, clang (the CI sanitizer build, docs/architecture.md "Build") with
// __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define MGP_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MGP_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef MGP_ADDRESS_SANITIZER
#define MGP_ADDRESS_SANITIZER 0
#endif
