# libFuzzer targets (tests/fuzz, CTest label fuzz): -DBAKE_FUZZ=ON with CC=clang CXX=clang++.
# Everything is instrumented for coverage (fuzzer-no-link) and built with ASan + UBSan; only the fuzz
# executables link libFuzzer's main (tests/fuzz/CMakeLists.txt).
option(BAKE_FUZZ "Build the libFuzzer targets in tests/fuzz (clang only)" OFF)
if(BAKE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "BAKE_FUZZ=ON needs clang: configure with CC=clang CXX=clang++")
  endif()
  # -O1 and line tables only: the usual fuzzing build, and much quicker to compile than -O2 -g.
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined -O1 -gline-tables-only)
  add_link_options(-fsanitize=address,undefined)
endif()
