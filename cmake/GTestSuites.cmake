# bake_gtest_suites(<target> LABEL <label> [SEPARATE <pattern>=<labels> ...])
#
# Registers a GoogleTest executable with CTest one test suite at a time rather than one test at a
# time: every test process loads the same few hundred shared libraries (about half a second here), so
# a thousand one-test processes spent most of their time starting. A suite with more than
# BAKE_TESTS_PER_ENTRY tests is split into shards (GTEST_TOTAL_SHARDS / GTEST_SHARD_INDEX), so the
# long suites still run in parallel. The list is read after each build, like gtest_discover_tests.
#
# Labels: suites named Data* get `data;slow` (they read the shared mesh set), suites named *Stiff* get
# `stiff`, the others <label>. Each SEPARATE pattern (a gtest filter such as *MillionTriangle*) takes
# the tests it matches out of their suite into an entry of their own with the extra labels given
# (`;`-separated lists written with `,`), so a tier or a stage can leave them out by label.
set(BAKE_TESTS_PER_ENTRY 24 CACHE STRING "Tests per CTest entry when a GoogleTest suite is split into shards")
set(_bake_gtest_suites_script ${CMAKE_CURRENT_LIST_DIR}/gtest_suites_list.cmake)

function(bake_gtest_suites target)
  cmake_parse_arguments(arg "" "LABEL" "SEPARATE" ${ARGN})
  set(listing ${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.cmake)
  string(REPLACE ";" "|" separate "${arg_SEPARATE}")
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -DEXECUTABLE=$<TARGET_FILE:${target}> -DOUTPUT=${listing} -DTARGET=${target}
            -DLABEL=${arg_LABEL} "-DSEPARATE=${separate}" -DPER_ENTRY=${BAKE_TESTS_PER_ENTRY}
            -DWORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR} -P ${_bake_gtest_suites_script}
    BYPRODUCTS ${listing}
    VERBATIM)
  # CTest reads the listing through a wrapper, so that a build folder whose test executables are not
  # built (scripts/test.sh --fuzz builds only the fuzz targets) still runs its other tests.
  set(wrapper ${CMAKE_CURRENT_BINARY_DIR}/${target}_suites_include.cmake)
  file(WRITE ${wrapper} "if(EXISTS \"${listing}\")\n  include(\"${listing}\")\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${wrapper})
endfunction()
