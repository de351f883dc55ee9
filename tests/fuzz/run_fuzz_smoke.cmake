# CTest fuzz.<harness>: fuzz for SECONDS from the seed corpus (copied, so the source tree never changes), then
# fail on any crash, sanitizer report, leak, timeout or out-of-memory input (libFuzzer exits non-zero and writes
# the input as crash-*/leak-*/timeout-*/oom-* into WORK/artifacts). Optional: DICT (a -dict file), SEED_SCRIPT
# run by PYTHON as "SEED_SCRIPT WORK/cases --fuzz-seeds WORK/corpus" to add generated seeds.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
file(GLOB seeds ${CORPUS}/*)
file(COPY ${seeds} DESTINATION ${WORK}/corpus)
# Generated seeds (fuzz_gltf: the validation corpus's self-contained cases) and a dictionary, where given.
if(SEED_SCRIPT)
  execute_process(COMMAND ${PYTHON} ${SEED_SCRIPT} ${WORK}/cases --fuzz-seeds ${WORK}/corpus RESULT_VARIABLE seeded
                  OUTPUT_QUIET)
  if(NOT seeded EQUAL 0)
    message(FATAL_ERROR "${SEED_SCRIPT} failed (${seeded})")
  endif()
endif()
set(dictionary "")
if(DICT)
  set(dictionary -dict=${DICT})
endif()
set(ENV{LSAN_OPTIONS} "suppressions=${SUPPRESSIONS}:print_suppressions=0")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
execute_process(
  # A fixed seed: the smoke run explores the same sequence of inputs every time (a slower machine a prefix of
  # it), so CI does not fail by chance on a
  # finding nobody has looked at; the documented long runs (doc/stability.md) take random seeds.
  COMMAND ${FUZZER} ${dictionary} -seed=1 -max_total_time=${SECONDS} -max_len=8192 -timeout=10 -rss_limit_mb=2048
          -print_final_stats=1 -artifact_prefix=${WORK}/artifacts/ ${WORK}/corpus
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(WRITE ${WORK}/log.txt "${out}${err}")
if(NOT rc EQUAL 0)
  string(LENGTH "${err}" n)
  if(n GREATER 6000)
    math(EXPR from "${n} - 6000")
    string(SUBSTRING "${err}" ${from} 6000 err)
  endif()
  file(GLOB found ${WORK}/artifacts/*)
  message(FATAL_ERROR "fuzzer exited with ${rc}; inputs: ${found}\n${err}")
endif()
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" runs "${err}")
message(STATUS "fuzz smoke ${SECONDS} s: ${runs}")
