// Whether a sanitizer owns malloc in this build, for the tests that count heap allocations.
//
// Those tests replace malloc (and its relatives) and forward to glibc's __libc_* functions. Under
// a sanitizer that must not happen: the sanitizer's runtime intercepts malloc itself.
// - AddressSanitizer (scripts/test-sanitizers.sh): a second definition would hand glibc blocks to
//   ASan's free.
// - ThreadSanitizer (scripts/test-tsan.sh): the replacement, compiled with -fsanitize=thread,
//   wins over TSan's interceptor and is called by the dynamic loader (dlsym's error message)
//   while TSan initialises its interceptors, before the main thread's state exists. Its
//   instrumented function entry then writes to that state: a segmentation fault before main(),
//   first seen as a crash of GoogleTest's test listing at build time.
// There WPG_TEST_SANITIZER_OWNS_MALLOC is defined, and the tests count through the sanitizer's
// allocation hook instead, which its allocator calls for every allocation.
#pragma once

#include <cstddef>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(thread_sanitizer)
#define WPG_TEST_SANITIZER_OWNS_MALLOC 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define WPG_TEST_SANITIZER_OWNS_MALLOC 1
#endif

#ifdef WPG_TEST_SANITIZER_OWNS_MALLOC
// Declared in <sanitizer/allocator_interface.h> (compiler-rt and GCC's libsanitizer alike).
extern "C" int __sanitizer_install_malloc_and_free_hooks(
    void (*malloc_hook)(const volatile void*, std::size_t),
    void (*free_hook)(const volatile void*));
#endif
