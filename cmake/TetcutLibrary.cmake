# tetcut_add_installed_library(NAME SOURCES...): the static library tetcut_NAME of the current
# folder, aliased tetcut::NAME, public headers in its include/ (style: fmt), installed and
# exported so that find_package(tetcut) gives tetcut::NAME (when TETCUT_INSTALL). For geometry,
# engine, invariants.
function(tetcut_add_installed_library name)
  set(target tetcut_${name})
  add_library(${target} STATIC ${ARGN})
  add_library(tetcut::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME ${target})
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(TETCUT_INSTALL)
    install(TARGETS ${target} EXPORT tetcutTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(DIRECTORY include/tetcut DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()
