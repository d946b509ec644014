# The Vivado files fpstereo-rtl writes (<prefix>.xdc, package_ip.tcl, block_design.tcl) parse as
# Tcl: every command completes (balanced braces, brackets and quotes). tclsh only reads the files
# and runs none of their commands, so no Vivado command is needed or executed. Run by ctest with
# FPSTEREO_RTL and WORK set.
find_program(TCLSH NAMES tclsh tclsh8.6)
if(NOT TCLSH)
  message(FATAL_ERROR "tclsh not found: install the Debian package tcl (scripts/setup.sh does)")
endif()
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

execute_process(COMMAND ${FPSTEREO_RTL} --preset C2 -o ${WORK}/c2 RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fpstereo-rtl --preset C2 -o ${WORK}/c2 failed (${rc}): ${err}")
endif()
file(GLOB xdc ${WORK}/c2/*.xdc)
list(LENGTH xdc xdc_count)
if(NOT xdc_count EQUAL 1)
  message(SEND_ERROR "expected one <prefix>.xdc in ${WORK}/c2, found ${xdc_count}")
endif()
foreach(file ${xdc} ${WORK}/c2/package_ip.tcl ${WORK}/c2/block_design.tcl)
  if(EXISTS ${file})
    check_tcl(${file} TRUE)
  else()
    message(SEND_ERROR "fpstereo-rtl did not write ${file}")
  endif()
endforeach()
