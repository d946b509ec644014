# The single-file output (`fpstereo-rtl ... > top.v`) lints clean with verilator --lint-only -Wall,
# as docs/command-line.md promises. Run by ctest with FPSTEREO_RTL and WORK set.
find_program(VERILATOR verilator REQUIRED)
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${FPSTEREO_RTL} --width 32 --height 8 --dmax 16 --uf 4 --window 5 --median 3
                OUTPUT_FILE ${WORK}/top.v RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fpstereo-rtl failed: ${rc}")
endif()
file(STRINGS ${WORK}/top.v modules REGEX "^module ")
list(GET modules 0 first)
string(REGEX REPLACE "^module ([A-Za-z0-9_]+).*" "\\1" top "${first}")
execute_process(COMMAND ${VERILATOR} --lint-only -Wall --top-module ${top} ${WORK}/top.v
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
  message(FATAL_ERROR "verilator --lint-only -Wall ${WORK}/top.v: exit ${rc}\n${err}")
endif()
message(STATUS "ok: ${WORK}/top.v (top ${top}) lints clean")
