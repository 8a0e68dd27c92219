# ctest script (cmake -P): installs the Python module from BUILD_DIR into a
# fresh prefix under WORK_DIR (component python) and imports it with
# PYTHONPATH=PREFIX/SITE_DIR, the directory /usr/bin/python3 imports from
# when the prefix is the default one.
#
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DSITE_DIR=... -DPYTHON=... -P install_and_import.cmake
foreach(variable BUILD_DIR WORK_DIR SITE_DIR PYTHON)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_and_import.cmake: -D${variable}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --component python
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed (${rc}):\n${out}\n${err}")
endif()
if(IS_ABSOLUTE "${SITE_DIR}")
  set(site ${SITE_DIR})
else()
  set(site ${prefix}/${SITE_DIR})
endif()

# PYTHONPATH comes before the site directories, where another copy may be
# installed; where the module came from is checked below. Not run in the
# build's python/ directory, whose copy `python -c` would import first.
execute_process(WORKING_DIRECTORY ${WORK_DIR} COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -c
  "import tilable_surfaces as t; print(t.__file__); print(t.KSetTilableSurface.__name__, t.curve.__name__)"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "import from ${site} failed (${rc}):\n${out}\n${err}")
endif()
string(FIND "${out}" "${site}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "the module was not imported from ${site}:\n${out}")
endif()
message(STATUS "imported ${out}")
