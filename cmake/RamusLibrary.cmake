# ramus_folder_library(NAME DIR [EXCLUDE regex] [DEPS ...])
# One static library per top-level folder, from the .cpp files below it. The folder's headers
# are included as "folder/name.h" from the project root.
function(ramus_folder_library name)
  cmake_parse_arguments(ARG "" "EXCLUDE" "DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(ARG_EXCLUDE)
    list(FILTER sources EXCLUDE REGEX "${ARG_EXCLUDE}")
  endif()
  if(sources)
    add_library(${name} STATIC ${sources})
    target_link_libraries(${name} PUBLIC ramus_options ${ARG_DEPS})
  else()
    # A folder whose code has not landed yet still gives a target to link against.
    add_library(${name} INTERFACE)
    target_link_libraries(${name} INTERFACE ramus_options ${ARG_DEPS})
  endif()
endfunction()
