# Script mode: a sequence target in engine mode on the engine seeds must stop on the first input
# that breaks the engine, with the finding's line (support/fuzz_failure.hpp) naming a manifold
# invariant, I5 or I6: what blind removal leaves.
execute_process(COMMAND "${TARGET}" -runs=0 "-engine=${ENGINE}" "${SEEDS}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "the engine passed every seed; expected a finding\n${err}")
endif()
if(NOT err MATCHES "tetcut-fuzz: I[56] violated after operation [0-9]+")
  message(FATAL_ERROR "exit ${rc} without a manifold finding:\n${err}")
endif()
string(REGEX MATCH "tetcut-fuzz: I[56][^\n]*" line "${err}")
message(STATUS "caught: ${line}")
