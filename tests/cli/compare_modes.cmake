# Runs `railmodal modes` twice with JSON output and compares the frequencies.
#   -DEXE=railmodal -DCOMPARE=compare_frequencies -DARGS_A="a|b" -DARGS_B="c|d" -DOUT=prefix -DTOLERANCE=1e-12
string(REPLACE "|" ";" ARGS_A "${ARGS_A}")
string(REPLACE "|" ";" ARGS_B "${ARGS_B}")
foreach(side A B)
  execute_process(COMMAND ${EXE} ${ARGS_${side}} --format json -o ${OUT}_${side}.json
                  RESULT_VARIABLE code ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "railmodal ${ARGS_${side}}: exit code ${code}\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${COMPARE} ${OUT}_A.json ${OUT}_B.json ${TOLERANCE}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the frequencies differ:\n${err}")
endif()
