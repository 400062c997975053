# ctest peers.bench_smoke: peers_bench on some of its sweeps, then the peers table with --check:
# tetcut leaves no singularity, no flat tet and no unresolved request, CGAL's face_status
# classification leaves none that our checker sees, every approach made its cuts, and blind
# removal leaves singular vertices on the gated sweep (the harness sees what it exists to see).
#
#   cmake -DBENCH=<peers_bench> -DTABLE=<peers_table.py> -DPYTHON=<python3> -DWORK_DIR=<dir>
#         -DFILTER=<benchmark regex> -P peers_bench_smoke.cmake
cmake_minimum_required(VERSION 3.25)

set(json "${WORK_DIR}/peers_smoke.json")
file(MAKE_DIRECTORY "${WORK_DIR}")
file(REMOVE "${json}")
execute_process(COMMAND "${BENCH}" "--benchmark_filter=${FILTER}" "--benchmark_out=${json}" --benchmark_out_format=json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "peers_bench exited ${rc}:\n${out}\n${err}")
endif()
execute_process(COMMAND "${PYTHON}" "${TABLE}" "${json}" --check RESULT_VARIABLE rc OUTPUT_VARIABLE table ERROR_VARIABLE err)
message(STATUS "${table}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "peers_table.py --check exited ${rc}:\n${err}")
endif()
