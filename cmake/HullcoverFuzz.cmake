# HULLCOVER_FUZZ (preset `fuzz`, scripts/fuzz.sh): builds the libFuzzer
# targets of tests/fuzz with clang. Every target of the project is compiled
# with libFuzzer's coverage hooks (-fsanitize=fuzzer-no-link), so the
# fuzzers see the branches of the library code they drive; only the fuzz
# executables link libFuzzer's own main (tests/fuzz/CMakeLists.txt). The
# hooks cost the unit tests little, so the same build, with
# HULLCOVER_SANITIZE, is also the sanitizer build CI runs the unit tier in.

if(HULLCOVER_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "HULLCOVER_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++ "
                        "(the CMake preset `fuzz` does; Debian packages clang and libclang-rt-14-dev)")
  endif()
  if(NOT HULLCOVER_SANITIZE)
    message(WARNING "HULLCOVER_FUZZ without HULLCOVER_SANITIZE: the fuzzers find crashes only, "
                    "not the memory errors and undefined behaviour that precede most of them")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
  if(HULLCOVER_SANITIZE)
    # UBSan's checks inside Eigen and the standard library keep clang from
    # inlining them (the list says why); ours keep every check.
    add_compile_options(-fsanitize-ignorelist=${CMAKE_CURRENT_LIST_DIR}/HullcoverFuzzUbsanIgnore.txt)
  endif()
endif()
