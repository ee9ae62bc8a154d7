# The size budget of the embeddable runtime (docs/runtime.md): a minimal program linking
# ramus_runtime, stripped, stays under BUDGET bytes. Run by ctest as
#   cmake -DSTRIP=... -DEXE=... -DOUT=... -DBUDGET=... -P check_size_budget.cmake
file(COPY_FILE "${EXE}" "${OUT}")
execute_process(COMMAND ${STRIP} "${OUT}" RESULT_VARIABLE rc ERROR_VARIABLE errors)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "strip failed: ${errors}")
endif()
file(SIZE "${OUT}" bytes)
if(bytes GREATER BUDGET)
  message(FATAL_ERROR "stripped ${OUT} is ${bytes} bytes, over the budget of ${BUDGET}")
endif()
message(STATUS "stripped minimal program: ${bytes} bytes (budget ${BUDGET})")
