// What a planted slowdown adds each time the function it wraps is entered (wrap_symbol.py makes
// the wrapper; bench/CMakeLists.txt builds each variant): a fixed amount of work the engine never
// does, so that a gate that must catch a slowdown can be shown to. Compiled once per variant:
//
//   TETCUT_PLANTED_TURNS        turns of a loop on a volatile sum: a load, an add and a store a
//                               turn, about 6 instructions with the loop's own (more instructions)
//   TETCUT_PLANTED_COLD_LINES   cache lines read from a 64 MiB buffer, each 4099 lines past the
//                               last, so that none is read again before the buffer has been walked:
//                               a miss in any cache under 64 MiB for a few instructions a line (more
//                               cache misses, next to no instructions)
//   TETCUT_PLANTED_NANOSECONDS  a wait of that long on the steady clock (more wall time, whatever
//                               the processor: for the paired wall-time comparison)
#include <chrono>
#include <cstddef>
#include <cstring>

#ifndef TETCUT_PLANTED_TURNS
#define TETCUT_PLANTED_TURNS 0
#endif
#ifndef TETCUT_PLANTED_COLD_LINES
#define TETCUT_PLANTED_COLD_LINES 0
#endif
#ifndef TETCUT_PLANTED_NANOSECONDS
#define TETCUT_PLANTED_NANOSECONDS 0
#endif

namespace {

#if TETCUT_PLANTED_COLD_LINES > 0
constexpr std::size_t kLines = std::size_t{1} << 20;  // 64 MiB of 64-byte lines
// Written once before main (outside any measured cut), so that natively every line has a page of
// its own rather than the zero page the kernel maps for memory never written.
struct ColdBuffer {
  unsigned char* bytes = new unsigned char[kLines * 64];
  std::size_t next = 0;
  ColdBuffer() { std::memset(bytes, 1, kLines * 64); }
};
ColdBuffer cold;
#endif

}  // namespace

extern "C" void tetcut_planted_work() {
#if TETCUT_PLANTED_TURNS > 0
  volatile unsigned sum = 0;
  for (unsigned k = 0; k < TETCUT_PLANTED_TURNS; ++k) sum = sum + k;
#endif
#if TETCUT_PLANTED_COLD_LINES > 0
  for (int i = 0; i < TETCUT_PLANTED_COLD_LINES; ++i) {
    (void)*static_cast<volatile unsigned char*>(cold.bytes + cold.next * 64);  // a read the compiler keeps
    cold.next = (cold.next + 4099) & (kLines - 1);
  }
#endif
#if TETCUT_PLANTED_NANOSECONDS > 0
  const auto until = std::chrono::steady_clock::now() + std::chrono::nanoseconds(TETCUT_PLANTED_NANOSECONDS);
  while (std::chrono::steady_clock::now() < until) {
  }
#endif
}
