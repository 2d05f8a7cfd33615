# `cmake --install` makes hullcover a CMake package: headers, the static
# module libraries, and hullcoverConfig.cmake (+ version file) exporting
#   hullcover::bvh       the runtime a game server links (geometry, FCL, libccd)
#   hullcover::core      the decomposer (geometry, mesh, covering: Assimp, Qhull)
#   hullcover::validate  the audit (bvh and core, OctoMap)
# Consumers write find_package(hullcover REQUIRED [COMPONENTS bvh core validate]).
#
# Each component is its own export set, so the config file can find the
# dependencies of the components asked for and no others: a server that
# asks only for bvh never needs Assimp, Qhull or OctoMap installed. The
# libraries are static, so a module's private dependencies still appear in
# its exported link interface (as $<LINK_ONLY:...>); that is why the config
# file finds them too.
#
# The export sets follow the layers (geometry <- bvh, geometry <- core,
# bvh + core <- validate): an export set may refer to targets of another
# one, and the config file includes them in that order.

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HULLCOVER_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/hullcover" CACHE STRING
    "Where hullcoverConfig.cmake is installed, relative to the install prefix")

# Installed names drop the build tree's hullcover_ prefix: the namespace
# hullcover:: is added on export.
set_target_properties(hullcover_geometry PROPERTIES EXPORT_NAME geometry)
set_target_properties(hullcover_mesh PROPERTIES EXPORT_NAME mesh)
set_target_properties(hullcover_covering PROPERTIES EXPORT_NAME covering)
set_target_properties(hullcover_lib PROPERTIES EXPORT_NAME core)
set_target_properties(hullcover_bvh PROPERTIES EXPORT_NAME bvh)
set_target_properties(hullcover_bvh_covering PROPERTIES EXPORT_NAME bvh_covering)
set_target_properties(hullcover_bvh_fcl PROPERTIES EXPORT_NAME bvh_fcl)
set_target_properties(hullcover_validate PROPERTIES EXPORT_NAME validate)

# hullcover_install_component(COMPONENT TARGETS target...)
# Installs the targets into the export set hullcover<Component>Targets; the
# modules' BUILD_INTERFACE include folders become <prefix>/include.
function(hullcover_install_component component)
  cmake_parse_arguments(ARG "" "" "TARGETS" ${ARGN})
  string(SUBSTRING "${component}" 0 1 first)
  string(TOUPPER "${first}" first)
  string(SUBSTRING "${component}" 1 -1 rest)
  set(export_set "hullcover${first}${rest}Targets")
  install(TARGETS ${ARG_TARGETS}
    EXPORT ${export_set}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT ${export_set}
    NAMESPACE hullcover::
    DESTINATION ${HULLCOVER_INSTALL_CMAKEDIR})
endfunction()

hullcover_install_component(geometry TARGETS hullcover_geometry)
hullcover_install_component(bvh TARGETS hullcover_bvh hullcover_bvh_fcl)
hullcover_install_component(core TARGETS hullcover_mesh hullcover_covering hullcover_lib)
hullcover_install_component(validate TARGETS hullcover_validate hullcover_bvh_covering)

# Public headers only: every module keeps its kernels in src/.
foreach(module_dir lib/geometry lib/mesh lib/covering bvh validate)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${module_dir}/include/"
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    FILES_MATCHING PATTERN "*.h")
endforeach()

# The command line tool, for baking .hcw files on the machine that builds
# the game. Not part of the export: nothing links an executable.
install(TARGETS hullcover RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/hullcoverConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/hullcoverConfig.cmake"
  INSTALL_DESTINATION ${HULLCOVER_INSTALL_CMAKEDIR})
# 0.x: a minor release may change the API, so only the same minor matches.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/hullcoverConfigVersion.cmake"
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)
install(FILES
  "${PROJECT_BINARY_DIR}/hullcoverConfig.cmake"
  "${PROJECT_BINARY_DIR}/hullcoverConfigVersion.cmake"
  DESTINATION ${HULLCOVER_INSTALL_CMAKEDIR})
