# Every dependency comes from a Debian package through CMake's own package
# config. A missing one stops the configure step with the package to install.

function(hullcover_require package debian_package)
  find_package(${package} ${ARGN} QUIET)
  if(NOT ${package}_FOUND)
    message(FATAL_ERROR
      "hullcover needs ${package}: install the Debian package '${debian_package}' "
      "(apt-get install ${debian_package}, or run scripts/setup.sh).")
  endif()
endfunction()

hullcover_require(Eigen3 libeigen3-dev CONFIG)
hullcover_require(assimp libassimp-dev CONFIG)
hullcover_require(Qhull libqhull-dev CONFIG)
hullcover_require(ccd libccd-dev CONFIG)
hullcover_require(fcl libfcl-dev CONFIG)
hullcover_require(octomap liboctomap-dev CONFIG)
hullcover_require(CLI11 libcli11-dev CONFIG)
hullcover_require(nlohmann_json nlohmann-json3-dev CONFIG)
set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)
if(HULLCOVER_BUILD_TESTS)
  hullcover_require(GTest libgtest-dev CONFIG)
endif()
if(HULLCOVER_BUILD_BENCHMARKS)
  hullcover_require(benchmark libbenchmark-dev CONFIG)
endif()
