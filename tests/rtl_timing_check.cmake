# The Verilator test bench's timing check works: a small design whose stated timing is altered
# must fail. Run by ctest with FPSTEREO_RTL, VERIFY_RTL (scripts/verify-rtl.sh), BUILD_DIR and WORK
# set; one bench build and a two-frame run, well under a minute.
#
# fpstereo-tb requires the throughput run (no idle cycles, no backpressure) to measure exactly what
# the design states in the banner of its top file: the cycles per frame and the first-output
# latency. This test generates a design, states one cycle more per frame everywhere the bench
# reads the figure (the banner of every file, CYCLES_PER_FRAME_VALUE in <prefix>_regs.h and the
# CYCLES_PER_FRAME word the top hands its control block, so the register checks still agree) and
# one cycle more of first-output latency in the banners, then requires both FAIL lines, exit 1,
# and nothing else wrong. The unaltered designs pass: every rtl_* test runs the same check.
file(REMOVE_RECURSE ${WORK})
set(rtl ${WORK}/rtl)
execute_process(COMMAND ${FPSTEREO_RTL} --width 32 --height 8 --dmax 16 --uf 4 --window 3 --median 0 -o ${rtl}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fpstereo-rtl failed (${rc}): ${err}")
endif()

# What the design states (the banner of its top file, the first of filelist.f).
file(STRINGS ${rtl}/filelist.f files REGEX "\\.v$")
list(GET files 0 top)
file(READ ${rtl}/${top} text)
if(NOT text MATCHES "expected cycles per frame without stalls: ([0-9]+) ")
  message(FATAL_ERROR "${top}: the banner states no cycles per frame")
endif()
set(cycles ${CMAKE_MATCH_1})
if(NOT text MATCHES "to the first output handshake: ([0-9]+) cycles")
  message(FATAL_ERROR "${top}: the banner states no first-output latency")
endif()
set(latency ${CMAKE_MATCH_1})
math(EXPR wrong_cycles "${cycles} + 1")
math(EXPR wrong_latency "${latency} + 1")

# Replaces `from` by `to` in rtl/<file>, which must hold it `count` times.
function(alter file from to count)
  file(READ ${rtl}/${file} text)
  string(LENGTH "${text}" before)
  string(REPLACE "${from}" "" without "${text}")
  string(LENGTH "${without}" after)
  string(LENGTH "${from}" length)
  math(EXPR found "(${before} - ${after}) / ${length}")
  if(NOT found EQUAL count)
    message(FATAL_ERROR "${file}: '${from}' found ${found} times, expected ${count}: the generator's output changed, "
                        "adapt tests/rtl_timing_check.cmake")
  endif()
  string(REPLACE "${from}" "${to}" text "${text}")
  file(WRITE ${rtl}/${file} "${text}")
endfunction()

foreach(f IN LISTS files)
  alter(${f} "without stalls: ${cycles} " "without stalls: ${wrong_cycles} " 1)
  alter(${f} "first output handshake: ${latency} cycles" "first output handshake: ${wrong_latency} cycles" 1)
endforeach()
# The INFO words of the control block, word 11 (CYCLES_PER_FRAME) the fifth from the left.
alter(${top} "32'd${cycles}," "32'd${wrong_cycles}," 1)
file(GLOB header RELATIVE ${rtl} ${rtl}/*_regs.h)
file(READ ${rtl}/${header} header_text)
if(NOT header_text MATCHES "(#define [A-Z0-9_]+_CYCLES_PER_FRAME_VALUE +)${cycles}u")
  message(FATAL_ERROR "${header}: no CYCLES_PER_FRAME_VALUE ${cycles}u")
endif()
alter(${header} "${CMAKE_MATCH_0}" "${CMAKE_MATCH_1}${wrong_cycles}u" 1)

execute_process(COMMAND ${VERIFY_RTL} --build-dir ${BUILD_DIR} --tb-opt auto --rtl-dir ${rtl} -- --idle 0 --backpressure 0
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "the bench on the altered design (stated ${wrong_cycles} cycles per frame and a first-output "
               "latency of ${wrong_latency}; generated with ${cycles} and ${latency}), exit ${rc}:\n${out}${err}")
set(expected
    "FAIL: measured ${cycles} cycles per frame, the design states ${wrong_cycles}\n"
    "FAIL: measured a first-output latency of ${latency} cycles, the design states ${wrong_latency}\n"
    "registers: VERSION="
    " CYCLES_PER_FRAME=${wrong_cycles} PIXELS_PER_BEAT="  # read back from the altered INFO word, no error
    "FAIL: 4 frames compared, 0 mismatching pixels, 0 protocol errors, 0 register errors, 2 timing errors\n")
foreach(line IN LISTS expected)
  string(FIND "${out}" "${line}" at)
  if(at EQUAL -1)
    message(SEND_ERROR "the bench's output lacks '${line}'")
  endif()
endforeach()
if(NOT rc EQUAL 1)
  message(SEND_ERROR "the bench exited with ${rc}, expected 1 (a timing error)")
endif()

# --levels shapes generated textures only: with real images it is an error, not silently ignored
# (the bench built above is reused).
string(REPEAT "1 2 3 4 5 6 7 8 " 32 pixels)
file(WRITE ${WORK}/levels.pgm "P2\n32 8\n255\n${pixels}\n")
execute_process(COMMAND ${VERIFY_RTL} --build-dir ${BUILD_DIR} --tb-opt auto --rtl-dir ${rtl} --
                        --left ${WORK}/levels.pgm --right ${WORK}/levels.pgm --levels 4
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${err}" "--levels" at)
if(NOT rc EQUAL 2 OR at EQUAL -1)
  message(SEND_ERROR "the bench with --left and --levels: expected exit 2 naming --levels, got ${rc}: ${err}")
endif()
