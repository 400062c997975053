# Script mode: build the consumer in tests/consumer/project against a tetcut package and run it.
#   MODE install     install this build into a private prefix, check that the installed headers
#                    are exactly installed_headers.txt (the public API: no internal header), and
#                    use the installed package (CMAKE_PREFIX_PATH).
#   MODE build_tree  use the package this build tree exports (tetcut_DIR), nothing installed.
# The consumer compiles every header the package gives on its own, then cuts a box.
file(REMOVE_RECURSE "${WORK_DIR}")

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGV}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

if(MODE STREQUAL "install")
  set(prefix "${WORK_DIR}/prefix")
  run(${CMAKE_COMMAND} --install "${TETCUT_BINARY_DIR}" --prefix "${prefix}")
  file(GLOB_RECURSE installed RELATIVE "${prefix}/include" "${prefix}/include/*")
  list(SORT installed)
  file(STRINGS "${EXPECTED_HEADERS}" expected)
  list(SORT expected)
  if(NOT installed STREQUAL expected)
    string(REPLACE ";" "\n  " installed_lines "${installed}")
    message(FATAL_ERROR "installed headers differ from ${EXPECTED_HEADERS}:\n  ${installed_lines}")
  endif()
  set(find_tetcut "-DCMAKE_PREFIX_PATH=${prefix}")
elseif(MODE STREQUAL "build_tree")
  set(find_tetcut "-Dtetcut_DIR=${TETCUT_BINARY_DIR}")
else()
  message(FATAL_ERROR "MODE must be install or build_tree, not '${MODE}'")
endif()

run(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE_DIR}" -B "${WORK_DIR}/build" -G Ninja
    "${find_tetcut}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("${WORK_DIR}/build/consumer")
if(NOT last_output MATCHES "tets 48 hash [0-9a-f]+ valid 1\ncut ok 1 removed [1-9][0-9]* valid 1\ncompacted stale 0 refused 0")
  message(FATAL_ERROR "unexpected consumer output: ${last_output}")
endif()
message(STATUS "consumer ran: ${last_output}")

# The template engine adapter (examples/engine_adapter), built as an outside project would build
# its own: against the same package, into a shared library of its own, then loaded and driven by
# this build's `tetcut check-engine`, which must find blind removal's singular vertices (exit 1).
if(TETCUT_EXE STREQUAL "")
  return()
endif()
run(${CMAKE_COMMAND} -S "${ADAPTER_SOURCE_DIR}" -B "${WORK_DIR}/adapter" -G Ninja
    "${find_tetcut}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}"
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
run(${CMAKE_COMMAND} --build "${WORK_DIR}/adapter")
execute_process(COMMAND "${TETCUT_EXE}" check-engine --engine "${WORK_DIR}/adapter/libtetcut_engine_blind.so"
                        --mesh "${CORPUS_DIR}/meshes/cylinder.msh" --cuts 8
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT out MATCHES "adapter 'blind'" OR NOT out MATCHES "I5 manifold vertex shells")
  message(FATAL_ERROR "check-engine on the outside adapter: exit ${rc}\n${out}\n${err}")
endif()
message(STATUS "outside adapter checked: ${out}")
