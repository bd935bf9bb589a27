# cmake -DPROGRAM=exe -DOUTPUT=file -P run_and_check_output.cmake
# Runs `PROGRAM OUTPUT` after removing OUTPUT, and fails unless the program succeeds and OUTPUT
# exists and is not empty.
file(REMOVE "${OUTPUT}")
execute_process(COMMAND "${PROGRAM}" "${OUTPUT}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed: ${status}")
endif()
if(NOT EXISTS "${OUTPUT}")
  message(FATAL_ERROR "${PROGRAM} did not write ${OUTPUT}")
endif()
file(SIZE "${OUTPUT}" size)
if(size EQUAL 0)
  message(FATAL_ERROR "${OUTPUT} is empty")
endif()
message(STATUS "${OUTPUT}: ${size} bytes")
