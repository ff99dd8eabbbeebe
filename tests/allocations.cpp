// Counting heap allocations (allocations.hpp), for the unit tests and the zero-allocation test: by
// AddressSanitizer's malloc hook under the sanitizers, else by counting global allocation functions.
#include "allocations.hpp"

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define KANE_TEST_ASAN 1
#endif
#endif

namespace {
long counted = 0;
}

long allocations::count() { return counted; }

#ifdef KANE_TEST_ASAN
#include <sanitizer/allocator_interface.h>
namespace {
void on_malloc(const volatile void*, std::size_t) { ++counted; }
void on_free(const volatile void*) {}
const int hooked = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
}  // namespace
#else
void* operator new(std::size_t n) {
  ++counted;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif
