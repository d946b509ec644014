# The templates' parameter invariants (rtl_templates/*.v): a few modules linted alone with
# `verilator --lint-only -Wall`, once with a valid parameter set (no warning) and once with a
# violating one (elaboration fails, naming the rule); one violation also through Yosys and
# iverilog, so all three tools are seen to report it. Run by ctest with TEMPLATES set.
find_program(VERILATOR verilator)
find_program(YOSYS yosys)
find_program(IVERILOG iverilog)
foreach(tool VERILATOR YOSYS IVERILOG)
  if(NOT ${tool})
    message(FATAL_ERROR "${tool} not found: scripts/setup.sh installs it")
  endif()
endforeach()

# The module's file and the templates it instantiates, as paths.
function(template_files out top)
  set(files)
  foreach(m IN ITEMS ${top} ${ARGN})
    list(APPEND files ${TEMPLATES}/fpstereo_${m}.v)
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# verilator --lint-only -Wall on fpstereo_<top> with the -G overrides in `valid`: must pass
# silently; with those in `violating`: must fail and print `rule`.
function(check_module top valid violating rule)
  template_files(files ${top} ${ARGN})
  separate_arguments(valid)
  separate_arguments(violating)
  set(lint ${VERILATOR} --lint-only -Wall --top-module fpstereo_${top})
  execute_process(COMMAND ${lint} ${valid} ${files} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
    message(SEND_ERROR "fpstereo_${top} with valid parameters (${valid}): expected a clean lint, got ${rc}:\n"
                       "${out}${err}")
  endif()
  execute_process(COMMAND ${lint} ${violating} ${files} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${out}${err}" "fpstereo_invalid_parameters_${rule}" found)
  if(rc EQUAL 0 OR found EQUAL -1)
    message(SEND_ERROR "fpstereo_${top} with ${violating}: expected Verilator to fail naming ${rule}, got ${rc}:\n"
                       "${out}${err}")
  endif()
endfunction()

check_module(aggregator
  "-GW=60 -GPATHS=5 -GUF=4" "-GW=60 -GPATHS=5 -GUF=4 -GSEGMENT=29"
  aggregator_ROW_SLOTS_is_not_K_segments_of_SEGMENT_covering_W
  frame_row path_lanes path_minimum min_tree reduction_tree unique_join delay ram_sdp ram_async)
check_module(window "-GN=3 -GROW_SLOTS=40 -GADDR_W=6" "-GN=3 -GROW_SLOTS=40 -GADDR_W=5"
  window_ADDR_W_below_clog2_ROW_SLOTS ram_sdp)
check_module(min_tree "-GN=5 -GIDX_W=3" "-GN=9 -GIDX_W=3" reduction_tree_IDX_W_does_not_hold_N_minus_1
  reduction_tree unique_join)
check_module(sum_tree "-GN=7 -GREGISTER_LEVEL=3" "-GN=7 -GREGISTER_LEVEL=4" sum_tree_REGISTER_LEVEL_is_not_a_level)
check_module(subpixel_fit "-GK=4" "-GK=4 -GOUT_W=9" subpixel_fit_DISP_W_or_OUT_W_does_not_hold_DMAX_minus_1)
check_module(lr1_match "-GK=2 -GG=4 -GUF=8 -GDMAX=32" "-GK=2 -GG=4 -GUF=8 -GDMAX=24"
  DMAX_is_not_G_times_UF ram_async)
check_module(median_select "-GM=3 -GWORD_W=6" "-GM=9 -GWORD_W=6" median_select_M_is_not_3_5_or_7)
check_module(census "-GN=3" "-GN=4" census_N_is_not_odd_and_at_least_3)
check_module(fused_term "-GWEIGHT=8 -GTRUNC=40" "-GWEIGHT=8 -GTRUNC=40 -GLANES_LAT=4 -GLAT=4"
             fused_term_LAT_is_not_the_latency delay)
check_module(speckle "-GW=1242 -GS=100 -GWORD_W=12 -GR=32" "-GW=32 -GS=8 -GROWS=11"
  speckle_ROWS_below_S_plus_2_plus_ceil_S_over_4 ram_sdp ram_tdp)
check_module(speckle_stage "-GROW_SLOTS=40 -GG=4 -GS=6" "-GROW_SLOTS=40 -GG=2 -GS=6"
  speckle_stage_G_below_4 speckle ram_sdp ram_tdp)
check_module(wta "-GUF=16 -GLANE_W=4 -GLEVELS_PER_STAGE=2 -GTREE_LAT=2"
  "-GUF=16 -GLANE_W=4 -GLEVELS_PER_STAGE=2 -GTREE_LAT=1" reduction_tree_LAT_is_not_the_tree_latency
  delay min_tree reduction_tree unique_join)

# A data delay line is not reset: at the size of the ZSAD 7x7 view's delay at uf = dmax = 64
# (3,990 bits, 3 deep) it lints clean, where a reset to a 11,970-bit replication was Verilator's
# WIDTHCONCAT. A flag's delay line (RESET) is cleared and lints clean too.
foreach(params "-GWIDTH=3990 -GDEPTH=3" "-GWIDTH=30 -GDEPTH=12 -GRESET=1")
  separate_arguments(args UNIX_COMMAND "${params}")
  execute_process(COMMAND ${VERILATOR} --lint-only -Wall --top-module fpstereo_delay ${args} ${TEMPLATES}/fpstereo_delay.v
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT "${out}${err}" STREQUAL "")
    message(SEND_ERROR "fpstereo_delay with ${params}: expected a clean lint, got ${rc}:\n${out}${err}")
  endif()
endforeach()

# The same kind of violation through Yosys and iverilog: fpstereo_window with N = 2.
set(rule fpstereo_invalid_parameters_window_N_below_3)
template_files(files window ram_sdp)
string(REPLACE ";" " " file_words "${files}")
execute_process(
  COMMAND ${YOSYS} -q -p "read_verilog ${file_words}; chparam -set N 2 fpstereo_window; hierarchy -check -top fpstereo_window"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}${err}" "${rule}" found)
if(rc EQUAL 0 OR found EQUAL -1)
  message(SEND_ERROR "Yosys: expected fpstereo_window with N = 2 to fail naming ${rule}, got ${rc}:\n${out}${err}")
endif()
execute_process(COMMAND ${IVERILOG} -g2005 -P fpstereo_window.N=2 -s fpstereo_window -o /dev/null ${files}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}${err}" "${rule}" found)
if(rc EQUAL 0 OR found EQUAL -1)
  message(SEND_ERROR "iverilog: expected fpstereo_window with N = 2 to fail naming ${rule}, got ${rc}:\n${out}${err}")
endif()
# ... and a valid one through both, so the failure above is the rule's.
execute_process(
  COMMAND ${YOSYS} -q -p "read_verilog ${file_words}; chparam -set N 3 fpstereo_window; hierarchy -check -top fpstereo_window"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(SEND_ERROR "Yosys: fpstereo_window with N = 3 failed (${rc}):\n${out}${err}")
endif()
execute_process(COMMAND ${IVERILOG} -g2005 -P fpstereo_window.N=3 -s fpstereo_window -o /dev/null ${files}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(SEND_ERROR "iverilog: fpstereo_window with N = 3 failed (${rc}):\n${out}${err}")
endif()
