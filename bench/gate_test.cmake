# Proves the budget gate can fail: runs a short benchmark, then the gate on tightened budgets
# (must exit 1), on generous ones (must exit 0) and on a budget naming a missing figure (2).
set(results "${WORK_DIR}/gate-test-results.json")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(COMMAND "${BENCH}" "--benchmark_filter=BM_BuildMesh/16000|BM_BytesPerTet"
                "--benchmark_min_time=0.01" "--benchmark_out=${results}" "--benchmark_out_format=json"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "benchmark run failed (${rc})")
endif()
foreach(case "tightened;1" "generous;0" "missing;2")
  list(GET case 0 name)
  list(GET case 1 expected)
  execute_process(COMMAND "${PYTHON}" "${SOURCE_DIR}/bench/budget_gate.py" "${results}"
                  "${SOURCE_DIR}/bench/testdata/${name}_budgets.json"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "gate on ${name} budgets: exit ${rc}\n${out}${err}")
  if(NOT rc EQUAL expected)
    message(FATAL_ERROR "the gate on ${name} budgets exited ${rc}, expected ${expected}")
  endif()
endforeach()
