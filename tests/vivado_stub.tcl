# Runs a Vivado script of fpstereo-rtl (the XDC, package_ip.tcl or block_design.tcl) in plain
# tclsh against stand-ins for the Vivado commands it uses: each takes exactly the options the
# Vivado Tcl reference (UG835) documents for it, with its required options and the documented
# number of positional arguments, and fails on anything else. The stand-ins model just enough
# for the scripts' own checks: the top's ports come from the Verilog (read here), an interface's
# port maps are the top's ports named after it (as Vivado infers them), get_ports matches the
# top's ports. Nothing of Vivado runs; what this proves is that every command and option the
# scripts use exists as documented and that every port they name exists.
#   tclsh vivado_stub.tcl SCRIPT TOP_VERILOG
if {[llength $argv] != 2} {
  puts stderr "usage: tclsh vivado_stub.tcl SCRIPT TOP_VERILOG"
  exit 2
}
lassign $argv script top_verilog
set argv {}

# ---- The top's ports ----------------------------------------------------------------------------
set in [open $top_verilog]
set text [read $in]
close $in
set ::top_ports {}
foreach {match direction range name} [regexp -all -inline {(input|output)\s+wire\s+(\[\d+:0\]\s+)?(\w+)} $text] {
  lappend ::top_ports $name
}
if {[llength $::top_ports] == 0} {
  puts stderr "$top_verilog: no ports found"
  exit 1
}

# ---- Documented syntax ----------------------------------------------------------------------------
# command {options that take a value} {flags} {required options} min_positional max_positional
set ::syntax {
  create_project {-part} {-force -in_memory -ip -rtl_kernel -quiet -verbose} {} 0 2
  add_files {-fileset -of_objects -copy_to} {-norecurse -scan_for_includes -force -quiet -verbose} {} 0 -1
  set_property {-dict} {-quiet -verbose} {} 1 3
  get_property {} {-min -max -quiet -verbose} {} 2 2
  current_fileset {} {-constrset -simset -quiet -verbose} {} 0 1
  current_project {} {-quiet -verbose} {} 0 1
  update_compile_order {-fileset} {-quiet -verbose} {} 0 0
  close_project {} {-delete -quiet -verbose} {} 0 0
  update_ip_catalog {-add_ip -delete_ip -disable_ip -enable_ip -add_interface -repo_path} {-rebuild -create_index -update_module_ref -quiet -verbose} {} 0 0
  get_files {-filter -compile_order -used_in -of_objects} {-regexp -nocase -references -all -quiet -verbose} {} 0 -1
  ipx::package_project {-root_dir -vendor -library -name -version -taxonomy -set_current -archive_source_project -module} {-import_files -force -force_update_compile_order -generated_files -component -from_files -quiet -verbose} {} 0 0
  ipx::infer_bus_interfaces {} {-quiet -verbose} {} 2 2
  ipx::infer_bus_interface {} {-quiet -verbose} {} 3 3
  ipx::get_bus_interfaces {-of_objects -filter} {-regexp -quiet -verbose} {} 0 -1
  ipx::get_port_maps {-of_objects -filter} {-regexp -quiet -verbose} {} 0 -1
  ipx::get_bus_parameters {-of_objects -filter} {-regexp -quiet -verbose} {} 0 -1
  ipx::get_file_groups {-of_objects -filter} {-regexp -quiet -verbose} {} 0 -1
  ipx::get_files {-of_objects -filter -type} {-regexp -quiet -verbose} {} 0 -1
  ipx::associate_bus_interfaces {-busif -clock -reset} {-remove -clear -quiet -verbose} {} 1 1
  ipx::add_bus_parameter {} {-quiet -verbose} {} 2 2
  ipx::add_memory_map {} {-quiet -verbose} {} 2 2
  ipx::add_address_block {} {-quiet -verbose} {} 2 2
  ipx::add_user_parameter {} {-quiet -verbose} {} 2 2
  ipx::create_xgui_files {} {-quiet -verbose} {} 1 1
  ipx::update_checksums {} {-quiet -verbose} {} 1 1
  ipx::check_integrity {} {-kernel -xrt -quiet -verbose} {} 1 1
  ipx::save_core {} {-quiet -verbose} {} 1 1
  ipgui::add_page {-name -component -parent -display_name -layout} {-quiet -verbose} {-component} 0 0
  ipgui::add_param {-name -component -parent -display_name -layout -show_label -show_range -widget} {-quiet -verbose} {-name -component} 0 0
  ipgui::get_guiparamspec {-name -component} {-quiet -verbose} {-component} 0 0
  create_bd_design {-dir -cell -mode -bdsource} {-quiet -verbose} {} 1 1
  create_bd_cell {-vlnv -type -reference} {-quiet -verbose} {-type} 1 1
  apply_bd_automation {-rule -dict -config -opts} {-quiet -verbose} {-rule} 1 1
  get_bd_intf_pins {-filter -of_objects} {-regexp -hierarchical -quiet -verbose} {} 0 -1
  get_bd_pins {-filter -of_objects} {-regexp -hierarchical -quiet -verbose} {} 0 -1
  get_bd_cells {-filter -of_objects} {-regexp -hierarchical -quiet -verbose} {} 0 -1
  get_bd_nets {-filter -of_objects} {-regexp -hierarchical -boundary_type -quiet -verbose} {} 0 -1
  connect_bd_intf_net {-intf_net -boundary_type} {-quiet -verbose} {} 2 2
  connect_bd_net {-net} {-quiet -verbose} {} 1 -1
  assign_bd_address {-target_address_space -offset -range} {-export_to_file -import_from_file -external -dict -quiet -verbose} {} 0 -1
  regenerate_bd_layout {-hierarchy -layout_file -layout_string} {-routing -quiet -verbose} {} 0 0
  validate_bd_design {-design} {-force -quiet -verbose} {} 0 0
  save_bd_design {} {-quiet -verbose} {} 0 1
  make_wrapper {-files -fileset} {-top -testbench -inst_template -import -force -quiet -verbose} {-files} 0 0
  create_clock {-period -name -waveform} {-add -quiet -verbose} {-period} 0 1
  get_ports {-filter -of_objects} {-regexp -nocase -quiet -verbose} {} 0 -1
  get_clocks {-filter -of_objects} {-regexp -nocase -include_generated_clocks -quiet -verbose} {} 0 -1
  set_input_delay {-clock -reference_pin} {-clock_fall -rise -fall -max -min -add_delay -network_latency_included -source_latency_included -quiet -verbose} {} 2 2
  set_output_delay {-clock -reference_pin} {-clock_fall -rise -fall -max -min -add_delay -network_latency_included -source_latency_included -quiet -verbose} {} 2 2
}

# Parses a call against its documented syntax; returns {options positional} or fails.
proc parse_call {command arguments} {
  foreach {name valued flags required min max} $::syntax {
    if {$name ne $command} continue
    set options [dict create]
    set positional {}
    for {set i 0} {$i < [llength $arguments]} {incr i} {
      set word [lindex $arguments $i]
      if {[string match {-[a-z]*} $word] && ![string is double -strict $word]} {
        if {[lsearch -exact $valued $word] >= 0} {
          if {$i + 1 >= [llength $arguments]} {
            error "$command: option $word needs a value"
          }
          dict set options $word [lindex $arguments [incr i]]
        } elseif {[lsearch -exact $flags $word] >= 0} {
          dict set options $word 1
        } else {
          error "$command: $word is not a documented option"
        }
      } else {
        lappend positional $word
      }
    }
    foreach option $required {
      if {![dict exists $options $option]} {
        error "$command: the required option $option is missing"
      }
    }
    set count [llength $positional]
    if {$count < $min || ($max >= 0 && $count > $max)} {
      error "$command: $count positional arguments, documented: $min to [expr {$max < 0 ? "any" : $max}]"
    }
    return [list $options $positional]
  }
  error "$command: not a command this check knows (add it with its documented syntax)"
}

# ---- Stand-ins ------------------------------------------------------------------------------------
namespace eval ipx {}
namespace eval ipgui {}
set ::used {}
foreach {name valued flags required min max} $::syntax {
  proc $name args [format {
    lassign [parse_call %1$s $args] options positional
    lappend ::used %1$s
    return [model %1$s $options $positional]
  } [list $name]]
}

# A port of the top, or fail: the scripts must name only ports that exist.
proc top_port {name} {
  regsub {\[\*\]$} $name {} base
  if {[lsearch -exact $::top_ports $base] < 0} {
    error "port $name: the top has no such port"
  }
  return "port:$base"
}

proc model {command options positional} {
  switch -- $command {
    get_ports {
      set ports {}
      foreach pattern [join $positional] {
        lappend ports [top_port $pattern]
      }
      return $ports
    }
    ipx::get_bus_interfaces {
      # Vivado infers an interface for each stream and for s_axi_ctrl; clock and reset too.
      if {[llength $positional] == 0} {
        return {}
      }
      set name [lindex $positional 0]
      foreach port $::top_ports {
        if {[string match ${name}_* $port] || $port eq $name} {
          return [list "busif:$name"]
        }
      }
      return {}
    }
    ipx::get_port_maps {
      set busif [dict get $options -of_objects]
      regsub {^busif:} $busif {} name
      set maps {}
      foreach port $::top_ports {
        if {[string match ${name}_* $port]} {
          lappend maps "map:$port"
        }
      }
      return $maps
    }
    get_property {
      lassign $positional property object
      if {$property eq "physical_name" && [regsub {^map:} $object {} port]} {
        return $port
      }
      return "value:$property"
    }
    get_bd_nets {
      return {}
    }
    default {
      return [list "$command:[join $positional]"]
    }
  }
}

if {[catch {source $script} message]} {
  puts stderr "$script: $message"
  exit 1
}
puts "$script: [llength [lsort -unique $::used]] Vivado commands, every call as documented, every port named exists"
