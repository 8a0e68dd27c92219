# ctest script (cmake -P): installs the project from BUILD_DIR into a fresh
# prefix under WORK_DIR, configures and builds the consumer project against
# that prefix only, and runs its program on MESH with K tiles.
#
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DMESH=... -DK=... -DCXX_FLAGS_RELEASE=...
#         -P install_and_consume.cmake
# CXX_FLAGS_RELEASE: the testsuite's Release flags, so that the consumer is
# compiled as the tests are.
foreach(variable BUILD_DIR WORK_DIR MESH K CXX_FLAGS_RELEASE)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_and_consume.cmake: -D${variable}=... is required")
  endif()
endforeach()

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}${err}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed include/CGAL/Tilable_surfaces/make_k_set_tilable.h
                  include/CGAL/Tilable_surfaces/IO/write_OBJ.h
                  share/cmake/Tilable_surfaces/Tilable_surfacesConfig.cmake
                  share/cmake/Tilable_surfaces/Tilable_surfacesConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "not installed: ${prefix}/${installed}")
  endif()
endforeach()

# The consumer must see the installed package only: no package registry, and
# the source tree's headers are not on its include path (checked below).
run_step("configure the consumer" ${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR} -B ${consumer_build}
         -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=${CXX_FLAGS_RELEASE}" -DCMAKE_PREFIX_PATH=${prefix}
         -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)
file(READ ${consumer_build}/CMakeCache.txt cache)
string(REGEX MATCH "Tilable_surfaces_DIR:PATH=([^\n]*)" _ "${cache}")
if(NOT CMAKE_MATCH_1 STREQUAL "${prefix}/share/cmake/Tilable_surfaces")
  message(FATAL_ERROR "the consumer found Tilable_surfaces in '${CMAKE_MATCH_1}', not in ${prefix}")
endif()
file(READ ${consumer_build}/compile_commands.json commands)
get_filename_component(source_include ${CMAKE_CURRENT_LIST_DIR}/../../../include ABSOLUTE)
string(FIND "${commands}" "${source_include}" found)
string(FIND "${commands}" "${prefix}/include" found_installed)
if(NOT found EQUAL -1 OR found_installed EQUAL -1)
  message(FATAL_ERROR "the consumer does not compile against ${prefix}/include only:\n${commands}")
endif()

run_step("build the consumer" ${CMAKE_COMMAND} --build ${consumer_build} -j 2)
execute_process(COMMAND ${consumer_build}/app ${MESH} ${K} WORKING_DIRECTORY ${WORK_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "consumer app output:\n${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "K = ${K}, degree of flexibility" OR NOT out MATCHES "\\(tilable\\)"
   OR NOT EXISTS ${WORK_DIR}/tilable.off)
  message(FATAL_ERROR "the consumer's program failed (${rc}) or did not make the mesh tilable")
endif()
