# ctest peers.quality_peer_smoke: the quality peer on the start of the gated sweep, so that it
# cannot rot unnoticed (a CGAL upgrade, a change of tetcut's public API). Passes when the program
# exits 0 (which it does only when every region CGAL returned is valid: cells positive by the exact
# predicate, figures finite, volume kept, kept vertices unmoved) and its JSON says what a sane run
# says: cuts compared, every CGAL region non-empty, radius ratios in (0, 1], dihedral angles in
# (0, 70.6] degrees.
#
#   cmake -DPEER=<tetcut_quality_peer> -DWORK_DIR=<dir> -DARGS="--cuts;40" -DNAME=<x> -P quality_peer_smoke.cmake
cmake_minimum_required(VERSION 3.25)

set(json "${WORK_DIR}/quality_peer_${NAME}.json")
file(MAKE_DIRECTORY "${WORK_DIR}")
file(REMOVE "${json}")
execute_process(COMMAND "${PEER}" ${ARGS} --json "${json}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "tetcut_quality_peer ${ARGS} exited ${rc}:\n${out}\n${err}")
endif()
file(READ "${json}" text)

function(expect_in_range what value low high)  # low < value <= high
  if(NOT value GREATER low OR value GREATER high)
    message(FATAL_ERROR "${what} = ${value}, expected in (${low}, ${high}]\n${out}")
  endif()
endfunction()

string(JSON sampled GET "${text}" summary cuts_sampled)
string(JSON invalid GET "${text}" summary cgal_invalid)
expect_in_range("cuts handed to CGAL" "${sampled}" 0 1000)
if(NOT invalid EQUAL 0)
  message(FATAL_ERROR "${invalid} CGAL regions invalid\n${out}")
endif()

string(JSON cuts LENGTH "${text}" cuts)
math(EXPR last "${cuts} - 1")
set(checked 0)
foreach(i RANGE ${last})
  string(JSON created GET "${text}" cuts ${i} created)
  if(created GREATER 0)
    string(JSON rr GET "${text}" cuts ${i} created_quality min_radius_ratio)
    string(JSON dih GET "${text}" cuts ${i} created_quality min_dihedral_deg)
    expect_in_range("cut ${i}: tetcut's worst created radius ratio" "${rr}" 0 1)
    expect_in_range("cut ${i}: tetcut's worst created min dihedral" "${dih}" 0 70.6)
  endif()
  string(JSON kind ERROR_VARIABLE no_cgal TYPE "${text}" cuts ${i} cgal)
  if(no_cgal)
    continue()
  endif()
  foreach(field tets not_positive unmeasured min_radius_ratio min_dihedral_deg)
    string(JSON ${field} GET "${text}" cuts ${i} cgal after ${field})
  endforeach()
  string(JSON moved GET "${text}" cuts ${i} cgal frozen_vertices_moved)
  expect_in_range("cut ${i}: CGAL's cells" "${tets}" 0 100000)
  expect_in_range("cut ${i}: CGAL's worst radius ratio" "${min_radius_ratio}" 0 1)
  expect_in_range("cut ${i}: CGAL's worst min dihedral" "${min_dihedral_deg}" 0 70.6)
  if(NOT not_positive EQUAL 0 OR NOT unmeasured EQUAL 0 OR NOT moved EQUAL 0)
    message(FATAL_ERROR "cut ${i}: CGAL's region has ${not_positive} cells not positive, ${unmeasured} unmeasured, "
                        "${moved} kept vertices moved\n${out}")
  endif()
  math(EXPR checked "${checked} + 1")
endforeach()
if(NOT checked EQUAL sampled)
  message(FATAL_ERROR "the JSON lists ${checked} CGAL regions, its summary ${sampled}")
endif()
message(STATUS "${checked} CGAL regions checked")
