# One golden case: runs EXE with ARGS ('|'-separated) from SOURCE_DIR, writing ACTUAL, and fails
# unless ACTUAL equals EXPECTED byte for byte (showing the first lines of the difference). A run
# that fails is recorded as "exit code N" and its message (as tools/update_golden.sh writes it),
# followed by the report it wrote if any (a failed fft-check writes its whole report).
cmake_minimum_required(VERSION 3.25)  # IN_LIST
string(REPLACE "|" ";" args "${ARGS}")
get_filename_component(dir "${ACTUAL}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
file(REMOVE "${ACTUAL}")
if("@OUT@" IN_LIST args)
  list(TRANSFORM args REPLACE "^@OUT@$" "${ACTUAL}")
else()
  list(APPEND args -o "${ACTUAL}")
endif()
execute_process(COMMAND "${EXE}" ${args} WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE code
                OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  set(report "")
  if(EXISTS "${ACTUAL}")
    file(READ "${ACTUAL}" report)
  endif()
  file(WRITE "${ACTUAL}" "exit code ${code}\n${err}${report}")
endif()
if(NOT EXISTS "${EXPECTED}")
  message(FATAL_ERROR "no golden file ${EXPECTED}: run tools/update_golden.sh and review the new file")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${EXPECTED}" "${ACTUAL}" RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  # The first lines of the difference, as diff prints them (message() would reflow them).
  execute_process(COMMAND bash -c "diff -u \"$0\" \"$1\" | head -n 60" "${EXPECTED}" "${ACTUAL}")
  message(FATAL_ERROR "the output differs from ${EXPECTED} (if on purpose, run tools/update_golden.sh "
                      "and say why in the commit)")
endif()
