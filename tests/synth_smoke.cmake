# `fpstereo synth` end to end on a tiny configuration: the first run synthesises with Yosys, the
# second is served from the cache with the same figures; errors are one line with exit 2. Run by
# ctest with FPSTEREO and WORK set.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(cache ${WORK}/cache)
# 256 pixels wide, so that the code reorder RAM (five rows of two 8-bit codes a pixel) is the
# memory above 4096 bits that check_memories() needs.
set(config --width 256 --height 8 --dmax 16 --uf 16 --window 3 --median 0 --paths 0)

function(synth out_var err_var)
  execute_process(COMMAND ${FPSTEREO} synth ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fpstereo synth ${ARGN} failed (${rc}): ${err}")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction()

# A memory of more than 4096 bits that is not block RAM would cost LUTs the design does not need
# (synth-yosys.sh warns about the same threshold).
function(check_memories table)
  string(REGEX MATCHALL "\n  [^ \n]+ +[0-9]+x[0-9]+ -> [a-z]+" rows "${table}")
  set(large 0)
  foreach(row IN LISTS rows)
    string(REGEX MATCH "([^ \n]+) +([0-9]+)x([0-9]+) -> ([a-z]+)" _ "${row}")
    math(EXPR bits "${CMAKE_MATCH_2} * ${CMAKE_MATCH_3}")
    if(bits GREATER 4096)
      math(EXPR large "${large} + 1")
      if(NOT CMAKE_MATCH_4 STREQUAL "bram")
        message(SEND_ERROR "memory ${CMAKE_MATCH_1} (${bits} bits) became ${CMAKE_MATCH_4}, not BRAM")
      endif()
    endif()
  endforeach()
  if(large EQUAL 0)
    message(SEND_ERROR "no memory above 4096 bits in the report; the BRAM check proves nothing:\n${table}")
  endif()
endfunction()

string(TIMESTAMP start "%s")
# With --netlist and --log, which Yosys writes in the work folder and fpstereo puts in place after.
synth(first first_err ${config} --cache ${cache} --netlist ${WORK}/kept.json --log ${WORK}/kept.log)
string(TIMESTAMP stop "%s")
file(READ ${WORK}/kept.json netlist LIMIT 200)
file(READ ${WORK}/kept.log log LIMIT 2000)
if(NOT netlist MATCHES "^{" OR NOT log MATCHES "Yosys")
  message(SEND_ERROR "--netlist or --log not written: '${netlist}' '${log}'")
endif()
math(EXPR seconds "${stop} - ${start}")
message(STATUS "first run (Yosys): ${seconds} s\n${first}")
if(NOT first MATCHES "\n  LUT +([0-9]+) " OR CMAKE_MATCH_1 EQUAL 0)
  message(SEND_ERROR "no LUT count above 0 in the first run:\n${first}")
endif()
set(luts ${CMAKE_MATCH_1})
# The mapped netlist's depth (at least one LUT level) and a path that deep.
if(NOT first MATCHES "\n  logic depth +([0-9]+) LUT levels" OR CMAKE_MATCH_1 EQUAL 0)
  message(SEND_ERROR "no logic depth above 0 in the first run:\n${first}")
endif()
set(depth ${CMAKE_MATCH_1})
if(NOT first MATCHES "\n +${depth} +[0-9]+  [^ \n]+ -> [^ \n]+\n")
  message(SEND_ERROR "no path of ${depth} LUT levels:\n${first}")
endif()
string(FIND "${first}" "(cached)" cached_first)
if(NOT cached_first EQUAL -1)
  message(SEND_ERROR "the first run into an empty cache says (cached)")
endif()
if(first_err MATCHES "not block RAM")
  message(SEND_ERROR "synth-yosys.sh warned: ${first_err}")
endif()
check_memories("${first}")

synth(second second_err ${config} --cache ${cache})
string(FIND "${second}" "(cached)" cached_second)
string(REPLACE " (cached)" "" second_figures "${second}")
if(cached_second EQUAL -1 OR NOT second_figures STREQUAL first)
  message(SEND_ERROR "the second run should say (cached) and print the first run's figures; got:\n${second}")
endif()

synth(kv kv_err ${config} --cache ${cache} --kv)
if(NOT kv MATCHES "\nlut=${luts}\n" OR NOT kv MATCHES "\ncached=1\n$" OR NOT kv MATCHES "\ndepth_levels=${depth}\n"
   OR NOT kv MATCHES "\npath\\.1=${depth} [0-9]+ [^ \n]+ [^ \n]+\n")
  message(SEND_ERROR "--kv should give lut=${luts}, depth_levels=${depth}, path.1 and cached=1; got:\n${kv}")
endif()

# --hierarchical: its own record (not the flat one's), every module mapped once and the netlist
# flattened, so the block RAMs are the flat run's and the depth is of the whole design.
if(NOT kv MATCHES "\nbram36_equiv=([0-9.]+)\n")
  message(SEND_ERROR "no bram36_equiv in --kv:\n${kv}")
endif()
set(bram ${CMAKE_MATCH_1})
synth(hier hier_err ${config} --cache ${cache} --kv --hierarchical)
if(NOT hier MATCHES "\nhierarchical=1\n" OR NOT hier MATCHES "\ncached=0\n$"
   OR NOT hier MATCHES "\nbram36_equiv=${bram}\n" OR NOT hier MATCHES "\ndepth_levels=[1-9][0-9]*\n"
   OR NOT hier MATCHES "\nmem\\.[^=\n]+_ram_sdp\\$[0-9a-f]+\\.mem=")
  message(SEND_ERROR "--hierarchical should give hierarchical=1, cached=0, bram36_equiv=${bram}, a depth and "
                     "memories by module; got:\n${hier}")
endif()
if(NOT kv MATCHES "\nhierarchical=0\n")
  message(SEND_ERROR "the flat run should say hierarchical=0; got:\n${kv}")
endif()

# A record each, no leftover temporary file or work directory.
file(GLOB entries RELATIVE ${cache} ${cache}/* ${cache}/work/*)
set(stem "fps_census3_d16u16_[0-9a-f]+-default-default")
if(NOT entries MATCHES "^${stem}-[0-9a-f]+\\.kv;${stem}-hierarchical-[0-9a-f]+\\.kv;work$")
  message(SEND_ERROR "unexpected cache contents: ${entries}")
endif()

function(expect_error expected)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(STRIP "${err}" err)
  string(FIND "${err}" "\n" newline)
  string(FIND "${err}" "${expected}" found)
  if(NOT rc EQUAL 2 OR found EQUAL -1 OR NOT newline EQUAL -1)
    message(SEND_ERROR "${ARGN}\n  expected exit 2 and one line with '${expected}'\n  got exit ${rc}: ${err}")
  else()
    message(STATUS "ok: ${err}")
  endif()
endfunction()

expect_error("invalid config: uf = 5: must divide dmax (16)"
             ${FPSTEREO} synth --width 32 --height 8 --dmax 16 --uf 5 --cache ${cache})
expect_error("synth-yosys: unknown part 'xc9zz'" ${FPSTEREO} synth ${config} --part xc9zz --cache ${cache})
expect_error("cannot write '${WORK}/missing/netlist.json': no such directory"
             ${FPSTEREO} synth ${config} --netlist ${WORK}/missing/netlist.json --cache ${cache})
expect_error("synth-yosys: part xczu9eg is xcup, not xc7"
             ${FPSTEREO} synth ${config} --family xc7 --part xczu9eg --cache ${cache})
# A PATH holding only bash: the script runs and finds no Yosys.
find_program(BASH bash REQUIRED)
file(MAKE_DIRECTORY ${WORK}/bash_only)
file(CREATE_LINK ${BASH} ${WORK}/bash_only/bash SYMBOLIC)
expect_error("synth-yosys: yosys not found" ${CMAKE_COMMAND} -E env PATH=${WORK}/bash_only
             ${FPSTEREO} synth ${config} --cache ${cache} --no-cache)
