# Proves the budget gate can fail: runs a short benchmark, then the gate on tightened budgets
# (must exit 1), on generous ones (must exit 0) and on a budget naming a missing figure (2).
cmake_policy(SET CMP0007 NEW)  # the cases below hold empty list elements
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

# A wall time over budget is re-run by ci/bench before it fails (load only slows a run down):
# the gate takes the fastest run of a wall-time figure, lists the benchmarks to re-run only when
# nothing but wall times is over, and never lets a re-run clear an exact figure.
set(data "${SOURCE_DIR}/bench/testdata")
set(over "${WORK_DIR}/gate-test-over-time.txt")
foreach(case "confirm_slow.json;;1;BM_Cut/iterations:1"
             "confirm_slow.json;confirm_fast.json;0;"
             "confirm_slow.json;confirm_slow_again.json;1;BM_Cut/iterations:1"
             "confirm_allocating.json;confirm_fast.json;1;")
  list(GET case 0 first)
  list(GET case 1 rerun)
  list(GET case 2 expected)
  list(GET case 3 expected_over)
  set(confirm "")
  if(rerun)
    set(confirm --confirm "${data}/${rerun}")
  endif()
  execute_process(COMMAND "${PYTHON}" "${SOURCE_DIR}/bench/budget_gate.py" "${data}/${first}"
                  "${data}/confirm_budgets.json" ${confirm} --over-time "${over}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(READ "${over}" listed)
  string(STRIP "${listed}" listed)
  message(STATUS "gate on ${first} re-run by '${rerun}': exit ${rc}, re-run next: '${listed}'\n${out}${err}")
  if(NOT rc EQUAL expected OR NOT listed STREQUAL expected_over)
    message(FATAL_ERROR "the gate on ${first} re-run by '${rerun}' exited ${rc} listing '${listed}', "
                        "expected ${expected} listing '${expected_over}'")
  endif()
endforeach()
