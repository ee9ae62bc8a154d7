# The stages of ramus and the direction of their dependencies (docs/design.md):
#   core < grammar < compiler < formats, infer < backends < cli;  core < reconstruct < infer
# Each stage is one folder and one static library. A stage's sources see the folders of the
# stages below it and nothing else: the library's include path is a folder of the build tree
# holding links to exactly those folders (`ramus_stage_includes`), so an include that runs up
# the order, or sideways between formats/ and infer/, fails to compile instead of slipping in.

# ramus_stage_includes(TARGET SCOPE STAGE...)
# Gives TARGET an include root in which only the named top-level folders exist.
function(ramus_stage_includes target scope)
  set(root "${PROJECT_BINARY_DIR}/stages/${target}")
  file(MAKE_DIRECTORY "${root}")
  foreach(stage ${ARGN})
    if(NOT EXISTS "${root}/${stage}")
      file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${stage}" "${root}/${stage}" SYMBOLIC)
    endif()
  endforeach()
  target_include_directories(${target} ${scope} "${root}")
endfunction()

# ramus_stage_library(NAME SEES stage... [EXCLUDE regex] [DEPS ...])
# One static library from the .cpp files below the current folder; its sources may include
# the folders named by SEES (its own among them).
function(ramus_stage_library name)
  cmake_parse_arguments(ARG "" "EXCLUDE" "SEES;DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(ARG_EXCLUDE)
    list(FILTER sources EXCLUDE REGEX "${ARG_EXCLUDE}")
  endif()
  add_library(${name} STATIC ${sources})
  target_link_libraries(${name} PUBLIC ramus_options ${ARG_DEPS})
  ramus_stage_includes(${name} PUBLIC ${ARG_SEES})
endfunction()
