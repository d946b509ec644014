# Helpers shared by the ctest scripts run with `cmake -P` (hls_generated, rtl_generator_contract,
# tcl_syntax).

# Sets TCLSH, or stops the test with the package to install.
macro(require_tclsh)
  find_program(TCLSH NAMES tclsh tclsh8.6)
  if(NOT TCLSH)
    message(FATAL_ERROR "tclsh not found: install the Debian package tcl (scripts/setup.sh does)")
  endif()
endmacro()

# Fails the test for every file of dir_a that is not byte-identical in dir_b (determinism).
function(expect_identical_dirs dir_a dir_b)
  file(GLOB files RELATIVE ${dir_a} ${dir_a}/*)
  if(NOT files)
    message(SEND_ERROR "${dir_a} is empty: nothing to compare")
  endif()
  foreach(f IN LISTS files)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${dir_a}/${f} ${dir_b}/${f} RESULT_VARIABLE same)
    if(NOT same EQUAL 0)
      message(SEND_ERROR "${f} differs between two runs")
    endif()
  endforeach()
endfunction()
