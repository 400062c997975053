// Counting allocator for a benchmark's executable: every heap allocation in the process goes
// through these replacements of the global operator new, so that a benchmark can assert that a
// cut (or a consumer's update) allocates nothing once prepared. Include it in exactly one
// translation unit of an executable (the replacements are definitions).
//
// None of these is inlined: inlined, GCC 12 sees `malloc` freed by `operator delete` (or `free`
// on a pointer from `operator new`) and warns -Wmismatched-new-delete, although the pairs match
// underneath.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace tetcut::bench {
inline std::atomic<std::uint64_t> g_allocations{0};

// Allocations so far in the process.
inline std::uint64_t allocations() { return g_allocations.load(std::memory_order_relaxed); }
}  // namespace tetcut::bench

[[gnu::noinline]] void* operator new(std::size_t size) {
  tetcut::bench::g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new[](std::size_t size) { return operator new(size); }
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
