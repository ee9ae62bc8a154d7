# Proves ramus_runtime uses no Boost, Eigen or TBB, and (with the mesher of mesh/) none of the
# back end's mesh libraries: (1) none is among the libraries the target links, and (2) no header
# any of its sources includes, followed transitively by the compiler (-H), lies under boost/,
# eigen3/, Eigen/, tbb/, oneapi/, nanoflann/, OpenMesh/, draco/, stb/ or nlohmann/, or is
# tiny_gltf.h or meshoptimizer.h. Run by ctest as
#   cmake -DCXX=... -DROOT=... -DSOURCES=a.cpp|b.cpp -DLIBS=x|y -P check_no_heavy_deps.cmake
string(REPLACE "|" ";" SOURCES "${SOURCES}")
string(REPLACE "|" ";" LIBS "${LIBS}")
set(forbidden "(^|[/:])(boost|Boost|eigen3|Eigen|Eigen3|tbb|TBB|oneapi|nanoflann|OpenMesh|OpenMeshCore|draco|stb|nlohmann|nlohmann_json|TinyGLTF|tiny_gltf[.]h|meshoptimizer|meshoptimizer[.]h)([/:]|$)")
foreach(lib ${LIBS})
  if(lib MATCHES "${forbidden}")
    message(FATAL_ERROR "ramus_runtime links ${lib}")
  endif()
endforeach()
set(count 0)
foreach(src ${SOURCES})
  if(NOT IS_ABSOLUTE "${src}")
    set(src "${ROOT}/runtime/${src}")
  endif()
  # -H lists every header actually included, system headers too (where Boost and TBB would
  # live), one per line after dots for the depth. Not -M: clang's -M also lists the files that
  # `__has_include` merely finds (libstdc++'s pstl_config.h asks for <tbb/tbb.h>).
  execute_process(COMMAND ${CXX} -std=c++20 -I${ROOT} -H -fsyntax-only ${src}
    OUTPUT_VARIABLE ignored ERROR_VARIABLE tree RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cannot scan ${src}: ${tree}")
  endif()
  string(REGEX MATCHALL "(^|\n)[.]+ [^\n]+" lines "${tree}")
  set(deps "")
  foreach(line ${lines})
    string(REGEX REPLACE "^\n?[.]+ " "" dep "${line}")
    list(APPEND deps "${dep}")
  endforeach()
  if(deps STREQUAL "")
    message(FATAL_ERROR "${src}: the compiler listed no included header")
  endif()
  foreach(dep ${deps})
    if(dep MATCHES "${forbidden}")
      message(FATAL_ERROR "${src} includes ${dep}")
    endif()
  endforeach()
  math(EXPR count "${count} + 1")
endforeach()
if(count LESS 5)
  message(FATAL_ERROR "expected the runtime's sources, got ${count}")
endif()
message(STATUS "ramus_runtime: ${count} sources, no Boost/Eigen/TBB/tinygltf/OpenMesh/Draco/meshoptimizer")
