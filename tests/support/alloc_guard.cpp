// Global allocation counters behind NoAllocScope. See alloc_guard.h.
#include "alloc_guard.h"

#include <Eigen/Core>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace {
std::atomic<int> g_armed{0};
std::atomic<std::size_t> g_count{0};

void note_allocation() {
  if (g_armed.load(std::memory_order_relaxed) > 0) g_count.fetch_add(1, std::memory_order_relaxed);
}

#if defined(MPTRACK_SANITIZE)
// Under ASan the allocator must stay ASan's (interposing malloc would hand
// it blocks it never saw). Every malloc, new and Eigen allocation is
// counted through the sanitizer's allocation hook instead (installed below).
#define MPTRACK_ALLOC_VIA_SANITIZER_HOOK 1
void* raw_malloc(std::size_t n) { return std::malloc(n); }
#elif defined(__GLIBC__)
extern "C" void* __libc_malloc(std::size_t);
void* raw_malloc(std::size_t n) { return __libc_malloc(n); }  // the malloc below would count twice
#else
void* raw_malloc(std::size_t n) { return std::malloc(n); }
#endif

void* counted_new(std::size_t n) {
#if !defined(MPTRACK_ALLOC_VIA_SANITIZER_HOOK)
  note_allocation();
#endif
  void* p = raw_malloc(n == 0 ? 1 : n);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}
}  // namespace

namespace mptrack::test {

void eigen_assert_failed(const char* condition, const char* file, int line) {
  if (g_armed.load(std::memory_order_relaxed) > 0) {
    g_count.fetch_add(1, std::memory_order_relaxed);
  } else {
    std::fprintf(stderr, "eigen_assert failed: %s at %s:%d\n", condition, file, line);
    std::abort();
  }
}

NoAllocScope::NoAllocScope() : start_count_(g_count.load()) {
  g_armed.fetch_add(1);
  Eigen::internal::set_is_malloc_allowed(false);
}

NoAllocScope::~NoAllocScope() {
  if (g_armed.fetch_sub(1) == 1) Eigen::internal::set_is_malloc_allowed(true);
}

std::size_t NoAllocScope::allocations() const { return g_count.load() - start_count_; }

std::size_t counted_allocations() { return g_count.load(); }

}  // namespace mptrack::test

// Replacement global allocation functions ([new.delete]); the sized and
// array forms forward here too.
void* operator new(std::size_t n) { return counted_new(n); }
void* operator new[](std::size_t n) { return counted_new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
#if !defined(MPTRACK_ALLOC_VIA_SANITIZER_HOOK)
  note_allocation();
#endif
  return raw_malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
#if !defined(MPTRACK_ALLOC_VIA_SANITIZER_HOOK)
  note_allocation();
#endif
  return raw_malloc(n == 0 ? 1 : n);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

#if defined(MPTRACK_ALLOC_VIA_SANITIZER_HOOK)
// Declared here: GCC ships no <sanitizer/allocator_interface.h>; the
// runtimes of GCC and Clang both export this (compiler-rt interface).
extern "C" int __sanitizer_install_malloc_and_free_hooks(
    void (*malloc_hook)(const volatile void*, std::size_t), void (*free_hook)(const volatile void*));
namespace {
void sanitizer_malloc_hook(const volatile void*, std::size_t) { note_allocation(); }
void sanitizer_free_hook(const volatile void*) {}
[[maybe_unused]] const int g_hooks_installed =
    __sanitizer_install_malloc_and_free_hooks(sanitizer_malloc_hook, sanitizer_free_hook);
}  // namespace
#elif defined(__GLIBC__)
// glibc exports its allocator as __libc_*; interposing malloc itself also
// catches C-level allocations (Eigen's aligned_malloc, C libraries).
extern "C" {
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t n) {
  note_allocation();
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) {
  note_allocation();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) {
  note_allocation();
  return __libc_realloc(p, n);
}
}
#endif
