# Dependencies of the header-only Tilable_surfaces package, used both by the
# project's CMakeLists.txt and by the installed Tilable_surfacesConfig.cmake,
# so that a consumer gets exactly what the project's own programs get.
#
# tilable_surfaces_find_dependencies(<REQUIRED|QUIET>)
#   finds CGAL 5.5, Eigen 3.3 and nlohmann_json 3.
# tilable_surfaces_link_dependencies(<target>)
#   links them to the INTERFACE target <target>, and, when found, TBB (parallel
#   loops; unless TILABLE_SURFACES_WITH_TBB is OFF) and CHOLMOD (sparse
#   Cholesky, with the definition CGAL_TILABLE_SURFACES_USE_CHOLMOD; unless
#   TILABLE_SURFACES_WITH_CHOLMOD is OFF).
#
# Macros, not functions: find_package() must define its targets and variables
# in the caller's scope.

macro(tilable_surfaces_find_dependencies mode)
  find_package(CGAL 5.5 ${mode})
  find_package(Eigen3 3.3 ${mode})
  find_package(nlohmann_json 3 ${mode})  # JSON tile catalog and report
endmacro()

macro(tilable_surfaces_link_dependencies target)
  include(CGAL_Eigen3_support)
  target_link_libraries(${target} INTERFACE CGAL::CGAL CGAL::Eigen3_support nlohmann_json::nlohmann_json)

  if(NOT DEFINED TILABLE_SURFACES_WITH_TBB OR TILABLE_SURFACES_WITH_TBB)
    find_package(TBB QUIET)
    include(CGAL_TBB_support)
    if(TARGET CGAL::TBB_support)
      target_link_libraries(${target} INTERFACE CGAL::TBB_support)
      message(STATUS "Tilable_surfaces: TBB found, parallel loops enabled")
    else()
      message(STATUS "Tilable_surfaces: TBB not found, sequential only")
    endif()
  endif()

  if(NOT DEFINED TILABLE_SURFACES_WITH_CHOLMOD OR TILABLE_SURFACES_WITH_CHOLMOD)
    find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
    find_library(CHOLMOD_LIBRARY cholmod)
    if(CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY)
      target_include_directories(${target} INTERFACE ${CHOLMOD_INCLUDE_DIR})
      target_link_libraries(${target} INTERFACE ${CHOLMOD_LIBRARY})
      target_compile_definitions(${target} INTERFACE CGAL_TILABLE_SURFACES_USE_CHOLMOD)
      message(STATUS "Tilable_surfaces: CHOLMOD found: ${CHOLMOD_LIBRARY}")
    else()
      message(STATUS "Tilable_surfaces: CHOLMOD not found, Eigen's SimplicialLDLT is used")
    endif()
  endif()
endmacro()
