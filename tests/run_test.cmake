## Runs one ndda test; see tests/CMakeLists.txt for the kinds of tests.
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${COMMAND}
  WORKING_DIRECTORY ${WORKDIR}
  RESULT_VARIABLE _result
  OUTPUT_VARIABLE _stdout
  ERROR_VARIABLE _stderr)
file(WRITE ${WORKDIR}/screen-output "${_stdout}")
file(WRITE ${WORKDIR}/error-output "${_stderr}")
message("${_stdout}")
message("${_stderr}")

if(EXPECT_FAILURE)
  if(_result EQUAL 0)
    message(FATAL_ERROR "expected a non-zero exit code, got 0")
  endif()
  if(_result MATCHES "[Ss]egmentation|[Aa]bort|Child aborted")
    message(FATAL_ERROR "the program crashed instead of refusing the input: ${_result}")
  endif()
  file(STRINGS ${EXPECTED_REGEX_FILE} _patterns)
  foreach(_pattern ${_patterns})
    if(NOT "${_stdout}${_stderr}" MATCHES "${_pattern}")
      message(FATAL_ERROR "the output does not contain '${_pattern}'")
    endif()
  endforeach()
  # The refusal for doc/validation.md (scripts/validation_page.py reads
  # '@value' lines from *.log): the exit code and ndda's message, with the
  # test directory's path cut to 'tests/' so that it reads the same in
  # every clone.
  get_filename_component(_name ${WORKDIR} NAME)
  string(REGEX MATCH "ndda: error: [^\n]*" _message "${_stderr}${_stdout}")
  string(REGEX REPLACE "'/[^']*/(tests/[^'/]*)'" "'\\1'" _message "${_message}")
  file(WRITE ${WORKDIR}/refusal.log
    "@value ${_name}.exit_code ${_result}\n@value ${_name}.message ${_message}\n")
  return()
endif()

if(NOT _result EQUAL 0)
  message(FATAL_ERROR "the program exited with '${_result}'")
endif()

if(EXPECTED_OUTPUT)
  if(COMPARED_FILE)
    set(_compared ${WORKDIR}/${COMPARED_FILE})
  else()
    set(_compared ${WORKDIR}/screen-output)
  endif()
  execute_process(COMMAND ${NUMDIFF} -q -s " \t\n:=,;()[]" -r 1e-6 -a 1e-10
      ${EXPECTED_OUTPUT} ${_compared}
    RESULT_VARIABLE _diff_result)
  if(NOT _diff_result EQUAL 0)
    execute_process(COMMAND ${NUMDIFF} -s " \t\n:=,;()[]" -r 1e-6 -a 1e-10
      ${EXPECTED_OUTPUT} ${_compared})
    message(FATAL_ERROR "output differs from ${EXPECTED_OUTPUT}")
  endif()
endif()
