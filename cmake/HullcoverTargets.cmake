# hullcover_library(NAME SOURCES src... [PUBLIC deps...] [PRIVATE deps...])
# One module library: target hullcover_NAME, alias hullcover::NAME, its public
# headers in the calling folder's include/, the project's warnings (and
# sanitizers). Every module is built the same way, so it is written once.
function(hullcover_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(hullcover_${name} ${ARG_SOURCES})
  add_library(hullcover::${name} ALIAS hullcover_${name})
  # include/: the installed API. internal/: headers the project's own
  # modules, tools and tests share (files, threads, geometry kernels), never
  # installed; no header in include/ may include one.
  target_include_directories(hullcover_${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                                     $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/internal>)
  target_link_libraries(hullcover_${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  hullcover_target_defaults(hullcover_${name})
endfunction()
