# lidr-bench --animation on BART's Robots (issue 46), a few frames at a small size (no timing is asserted):
#  - both light set-ups, every mode of the registry (tiled with and without pre-Z), each frame rendered by each mode;
#  - the judged frames: every mode's image at 40 dB or better against forward-brute, and no light-pixel dropped from
#    the lists of the modes that keep them (tiled, clustered; LIDR too wherever no more lights overlap a pixel than
#    its budget of 16 holds: where more do, as in the many-light set-up, it drops the lowest-priority ones by
#    design, and is held to 40 dB over the pixels within its budget);
#  - the outputs: animation.csv with a row per frame and mode, animation.json, animation.md;
#  - bad input (no frames, a scene without animation, a missing --bart folder) fails with a message.
# Inputs: BENCH (executable), OUT (scratch folder), BART (../shared/bart-robots beside the source tree).
file(REMOVE_RECURSE ${OUT})

include(${CMAKE_CURRENT_LIST_DIR}/bench_test_helpers.cmake)  # run_bench

if(NOT EXISTS ${BART}/aff/Robot.aff)
  message(FATAL_ERROR "BART's Robots are not at ${BART} (../shared/bart-robots beside the source tree)")
endif()
set(frames 3)
run_bench(0 "animation.md" --scene bart-robots-many,bart-robots-few --bart ${BART} --animation ${frames}
          --reference-frames 2 --resolution 160x90 --no-plots --out ${OUT}/run)

file(READ ${OUT}/run/animation.json json)
string(JSON scenes LENGTH "${json}" scenes)
if(NOT scenes EQUAL 2)
  message(FATAL_ERROR "animation.json: ${scenes} scenes, expected 2")
endif()
set(rows 0)
math(EXPR last_scene "${scenes} - 1")
foreach(s RANGE ${last_scene})
  string(JSON name GET "${json}" scenes ${s} scene)
  string(JSON modes LENGTH "${json}" scenes ${s} modes)
  if(modes LESS 5)
    message(FATAL_ERROR "${name}: ${modes} modes; lidr, tiled twice, clustered and multi-pass expected")
  endif()
  math(EXPR last_mode "${modes} - 1")
  foreach(m RANGE ${last_mode})
    string(JSON mode GET "${json}" scenes ${s} modes ${m} mode)
    string(JSON count GET "${json}" scenes ${s} modes ${m} frames)
    string(JSON judged GET "${json}" scenes ${s} modes ${m} judged_frames)
    string(JSON psnr GET "${json}" scenes ${s} modes ${m} worst_psnr_within_budget_db)
    string(JSON over GET "${json}" scenes ${s} modes ${m} pixels_over_budget)
    if(NOT count EQUAL frames OR NOT judged EQUAL 2)
      message(FATAL_ERROR "${name} ${mode}: ${count} frames, ${judged} judged; expected ${frames} and 2")
    endif()
    if(psnr LESS 40)
      message(FATAL_ERROR "${name} ${mode}: worst PSNR ${psnr} dB against forward-brute")
    endif()
    string(JSON dropped ERROR_VARIABLE none GET "${json}" scenes ${s} modes ${m} dropped_light_pixels)
    if(NOT none AND NOT dropped EQUAL 0 AND over EQUAL 0)
      message(FATAL_ERROR "${name} ${mode}: ${dropped} light-pixels dropped from its lists, none over its budget")
    endif()
    if(NOT mode STREQUAL "lidr" AND NOT over EQUAL 0)
      message(FATAL_ERROR "${name} ${mode}: ${over} pixels over a budget; only LIDR has one")
    endif()
    math(EXPR rows "${rows} + ${count}")
  endforeach()
endforeach()
string(JSON lights GET "${json}" scenes 0 light_count)
string(JSON few GET "${json}" scenes 1 light_count)
if(NOT lights EQUAL 924 OR NOT few EQUAL 10)
  message(FATAL_ERROR "the set-ups have ${lights} and ${few} lights; expected 924 and 10")
endif()
file(STRINGS ${OUT}/run/animation.csv lines)
list(LENGTH lines count)
math(EXPR expected "${rows} + 1")
if(NOT count EQUAL expected)
  message(FATAL_ERROR "animation.csv: ${count} lines, expected ${expected} (a header and a row per frame and mode)")
endif()
if(NOT EXISTS ${OUT}/run/animation.md)
  message(FATAL_ERROR "animation.md missing")
endif()

run_bench(1 "--animation must be 1" --scene bart-robots-few --bart ${BART} --animation 0 --out ${OUT}/bad)
run_bench(1 "has no keyframe animation" --scene room --animation 2 --out ${OUT}/bad)
run_bench(1 "no BART Robots scene in" --scene bart-robots-many --bart ${OUT}/nowhere --animation 2 --out ${OUT}/bad)
