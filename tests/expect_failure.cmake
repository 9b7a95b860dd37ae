# Runs `wrc run SCRIPT` and passes when it exits non-zero with stderr matching REGEX.
execute_process(COMMAND ${WRC} run ${SCRIPT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0)
  message(FATAL_ERROR "wrc run ${SCRIPT} exited 0; expected a failure.\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT err MATCHES "${REGEX}")
  message(FATAL_ERROR "wrc run ${SCRIPT} exited ${rc} but stderr does not match '${REGEX}':\n${err}")
endif()
message(STATUS "exit ${rc}, stderr:\n${err}")
