// A fixed amount of extra work in every cut, for proving that the instruction gate has teeth.
// The engine's own copy does nothing: it is compiled without TETCUT_PLANTED_SLOWDOWN.
// bench/cut_instructions_planted compiles this file again with it and links it ahead of the
// engine, so that Cutter::cut() calls this version; ctest instruction_gate_catches_slowdown then
// runs the gate on both builds. About 18,000 extra instructions a cut (3,000 turns of the loop
// below): more than the gate's margin, so the planted build must fail it.
#include "cut/planted_slowdown.hpp"

namespace tetcut::detail {

void planted_slowdown() {
#ifdef TETCUT_PLANTED_SLOWDOWN
  // A volatile sum the compiler cannot fold: a load, an add and a store per turn, and the loop.
  volatile unsigned sum = 0;
  for (unsigned k = 0; k < 3000; ++k) sum = sum + k;
#endif
}

}  // namespace tetcut::detail
