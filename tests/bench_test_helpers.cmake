# What the lidr-bench test scripts share (run_bench_test.cmake, run_bench_animation_test.cmake).
# run_bench(EXPECT_RC EXPECT_TEXT ARGS...): lidr-bench ARGS (BENCH: the executable) must exit EXPECT_RC and, unless
# EXPECT_TEXT is empty, print something matching it; else the test fails with the command and its output.
function(run_bench expect_rc expect_text)
  execute_process(COMMAND ${BENCH} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "lidr-bench ${ARGN}: exit ${rc}, expected ${expect_rc}\n${out}\n${err}")
  endif()
  if(NOT "${expect_text}" STREQUAL "" AND NOT "${out}${err}" MATCHES "${expect_text}")
    message(FATAL_ERROR "lidr-bench ${ARGN}: output lacks '${expect_text}':\n${out}\n${err}")
  endif()
endfunction()
