#pragma once
// Counts heap allocations made through the global operator new, for "no allocation per
// evaluation" checks. Include in exactly one translation unit of an executable: it replaces the
// global allocation functions of that program.

#include <atomic>
#include <cstdlib>
#include <new>

namespace frictionlab::bench {
inline std::atomic<long long> g_allocations{0};
}  // namespace frictionlab::bench

// noinline: lets GCC see that delete frees what this new allocated (-Wmismatched-new-delete).
[[gnu::noinline]] void* operator new(std::size_t size) {
  frictionlab::bench::g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
