# bake_add_asset(<name> TOOL <tool> INPUT <file> OUTPUT <file> [ARGS <arg>...] [OUTPUTS <file>...]
#                [DEPENDS <file>...] [CACHE_DIR <dir>])
#
# Bakes INPUT into OUTPUT at build time with one of the bakers (geobake, groovebake, revolbake,
# tambake, strokebake, bakeshape): `TOOL INPUT -o OUTPUT ARGS... --depfile OUTPUT.d -q`. The baker's depfile names
# every file it reads, so files reached only through ARGS (a --sources file, a height map, a style's
# stroke image) also trigger a re-bake; DEPENDS adds more. OUTPUTS lists the other files the command
# writes (e.g. a --threshold texture), so the build knows them. A relative INPUT is read from the
# current source directory, a relative OUTPUT goes to the current binary directory. CACHE_DIR (or the
# variable BAKE_CACHE_DIR) passes --cache-dir: identical bakes are copied from that cache.
#
# Creates the target <name> (built by default) that depends on the outputs; its property
# BAKE_OUTPUTS lists them. TOOL is BakeTools::<tool> when that imported target exists (after
# find_package(BakeTools)), else a target or program of that name.
include_guard(GLOBAL)
if(CMAKE_VERSION VERSION_LESS 3.20)
  message(FATAL_ERROR "bake_add_asset needs CMake 3.20 or newer (DEPFILE with Ninja and Makefile generators)")
endif()

function(bake_add_asset name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "TOOL;INPUT;OUTPUT;CACHE_DIR" "ARGS;OUTPUTS;DEPENDS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "bake_add_asset(${name}): unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  foreach(required TOOL INPUT OUTPUT)
    if(NOT ARG_${required})
      message(FATAL_ERROR "bake_add_asset(${name}): ${required} is required")
    endif()
  endforeach()

  if(TARGET BakeTools::${ARG_TOOL})
    set(tool BakeTools::${ARG_TOOL})
  elseif(TARGET ${ARG_TOOL})
    set(tool ${ARG_TOOL})
  else()
    find_program(BAKE_PROGRAM_${ARG_TOOL} ${ARG_TOOL} REQUIRED)
    set(tool "${BAKE_PROGRAM_${ARG_TOOL}}")
  endif()
  set(tool_file "${tool}")
  if(TARGET ${tool})
    set(tool_file "$<TARGET_FILE:${tool}>")
  endif()

  get_filename_component(input "${ARG_INPUT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  get_filename_component(output "${ARG_OUTPUT}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  set(outputs "${output}")
  foreach(extra IN LISTS ARG_OUTPUTS)
    get_filename_component(extra "${extra}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
    list(APPEND outputs "${extra}")
  endforeach()
  set(depfile "${output}.d")

  if(NOT ARG_CACHE_DIR AND BAKE_CACHE_DIR)
    set(ARG_CACHE_DIR "${BAKE_CACHE_DIR}")
  endif()
  set(cache_args "")
  if(ARG_CACHE_DIR)
    set(cache_args --cache-dir "${ARG_CACHE_DIR}")
  endif()

  get_filename_component(output_dir "${output}" DIRECTORY)
  file(MAKE_DIRECTORY "${output_dir}")
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND "${tool_file}" "${input}" -o "${output}" ${ARG_ARGS} --depfile "${depfile}" ${cache_args} -q
    DEPENDS "${input}" "${tool_file}" ${ARG_DEPENDS}
    DEPFILE "${depfile}"
    COMMENT "Baking ${ARG_OUTPUT} with ${ARG_TOOL}"
    VERBATIM)
  add_custom_target(${name} ALL DEPENDS ${outputs})
  set_target_properties(${name} PROPERTIES BAKE_OUTPUTS "${outputs}")
endfunction()
