# The Vivado files fpstereo-rtl writes (<prefix>.xdc, package_ip.tcl, block_design.tcl) parse as
# Tcl: every command completes (balanced braces, brackets and quotes). Then each runs in tclsh
# against vivado_stub.tcl, stand-ins that accept exactly the documented syntax of each Vivado
# command the scripts use and know the generated top's ports: an undocumented option, a missing
# required one or a port the top lacks fails. No Vivado command is really executed. Run by ctest
# with FPSTEREO_RTL and WORK set.
include(${CMAKE_CURRENT_LIST_DIR}/script_helpers.cmake)
require_tclsh()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# tclsh check_tcl.tcl FILE: reads FILE line by line, joining lines until they make a complete
# command; exit 1 naming the first line of a command that never completes.
set(checker ${WORK}/check_tcl.tcl)
file(WRITE ${checker} [=[
set path [lindex $argv 0]
set in [open $path]
set command ""
set number 0
while {[gets $in line] >= 0} {
  incr number
  if {$command eq ""} {
    set first $number
  }
  append command $line "\n"
  if {[info complete $command]} {
    set command ""
  }
}
close $in
if {$command ne ""} {
  puts stderr "$path:$first: the command never completes (unbalanced braces, brackets or quotes)"
  exit 1
}
puts "$path: $number lines, every command complete"
]=])

function(check_tcl file expect_ok)
  execute_process(COMMAND ${TCLSH} ${checker} ${file} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(STRIP "${out}${err}" report)
  if(expect_ok AND NOT rc EQUAL 0)
    message(SEND_ERROR "${report}")
  elseif(NOT expect_ok AND rc EQUAL 0)
    message(SEND_ERROR "the checker accepted the broken ${file}")
  else()
    message(STATUS "${report}")
  endif()
endfunction()

# The checker itself must reject an unclosed command.
file(WRITE ${WORK}/unclosed.tcl "set x 1\nif {$x} {\n  puts \"x\"\n")
check_tcl(${WORK}/unclosed.tcl FALSE)

# tclsh vivado_stub.tcl FILE TOP: the file against the documented commands and the top's ports.
set(stub ${CMAKE_CURRENT_LIST_DIR}/vivado_stub.tcl)
function(check_commands file top expect_ok)
  execute_process(COMMAND ${TCLSH} ${stub} ${file} ${top} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(STRIP "${out}${err}" report)
  if(expect_ok AND NOT rc EQUAL 0)
    message(SEND_ERROR "${report}")
  elseif(NOT expect_ok AND rc EQUAL 0)
    message(SEND_ERROR "the command check accepted the broken ${file}")
  else()
    message(STATUS "${report}")
  endif()
endfunction()

# C2 with the AXI4-Lite control interface, and a design without it.
foreach(design c2 c2_fixed)
  set(flags --preset C2)
  if(design STREQUAL "c2_fixed")
    list(APPEND flags --no-axi-lite)
  endif()
  execute_process(COMMAND ${FPSTEREO_RTL} ${flags} -o ${WORK}/${design} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "fpstereo-rtl ${flags} -o ${WORK}/${design} failed (${rc}): ${err}")
  endif()
  file(GLOB xdc ${WORK}/${design}/*.xdc)
  file(GLOB top ${WORK}/${design}/*_top.v)
  list(LENGTH xdc xdc_count)
  if(NOT xdc_count EQUAL 1)
    message(SEND_ERROR "expected one <prefix>.xdc in ${WORK}/${design}, found ${xdc_count}")
  endif()
  # block_design.tcl stops unless package_ip.tcl has packaged the IP.
  file(WRITE ${WORK}/${design}/ip/component.xml "")
  foreach(file ${xdc} ${WORK}/${design}/package_ip.tcl ${WORK}/${design}/block_design.tcl)
    if(EXISTS ${file})
      check_tcl(${file} TRUE)
      check_commands(${file} ${top} TRUE)
    else()
      message(SEND_ERROR "fpstereo-rtl did not write ${file}")
    endif()
  endforeach()
endforeach()

# The command check itself must reject an undocumented option, a missing required option and a
# port the top does not have.
file(GLOB top ${WORK}/c2/*_top.v)
file(READ ${WORK}/c2/package_ip.tcl text)
string(REPLACE "-norecurse" "-no_recurse" text "${text}")
file(WRITE ${WORK}/c2/broken_option.tcl "${text}")
check_commands(${WORK}/c2/broken_option.tcl ${top} FALSE)
file(READ ${WORK}/c2/block_design.tcl text)
string(REPLACE "create_bd_cell -type ip -vlnv $ip_vlnv stereo" "create_bd_cell -vlnv $ip_vlnv stereo" text "${text}")
file(WRITE ${WORK}/c2/broken_required.tcl "${text}")
check_commands(${WORK}/c2/broken_required.tcl ${top} FALSE)
file(GLOB xdc ${WORK}/c2/*.xdc)
file(READ ${xdc} text)
string(REPLACE "s_axis_left_tuser" "s_axis_left_tusr" text "${text}")
file(WRITE ${WORK}/c2/broken_port.xdc "${text}")
check_commands(${WORK}/c2/broken_port.xdc ${top} FALSE)
