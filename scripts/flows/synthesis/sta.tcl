# OpenSTA run of scripts/flows/synthesis/silicon.sh: reads the libraries and the mapped netlist, finds
# T_sta (the smallest clock period with no negative setup slack, bisection to 0.01 ns),
# and at T_sta writes the reports, the SDC and the SDF. Variables from the caller (sta
# -exit with `set` lines before this file): lib, rom_lib, netlist, top, top_dir, out;
# after layout (scripts/flows/layout/layout.sh) also spef, the routed wires' R and C, and rom_lib may
# be empty (a block without ROM macros).
read_liberty $lib
if {$rom_lib ne ""} { read_liberty $rom_lib }
read_verilog $netlist
link_design $top
if {[info exists spef]} { read_spef $spef }
source $top_dir/constraints.tcl

proc worst_setup_slack {T} {
  constrain $T
  set s [sta::worst_slack -max]
  return $s
}

# Bisection: the slack grows with T (every constraint is a fraction or a multiple of T).
set lo 0.5
set hi 200.0
if {[worst_setup_slack $hi] < 0} {
  puts "sta.tcl: negative slack even at $hi ns"
  exit 1
}
while {$hi - $lo > 0.01} {
  set mid [expr {($lo + $hi) / 2.0}]
  if {[worst_setup_slack $mid] < 0} { set lo $mid } else { set hi $mid }
}
set t_sta [format %.2f $hi]
constrain $t_sta
set f [open $out/sta_summary.txt w]
puts $f "t_sta_ns $t_sta"
puts $f "worst_slack_ns [format %.4f [sta::worst_slack -max]]"
close $f

write_sdc -no_timestamp $out/constraints.sdc
write_sdf -no_timestamp -digits 4 $out/device.sdf

# The named paths of the top, each worst path in full (the report counts its cells).
# After layout the netlist is flat and its instances renamed by qflow (NAND2X1_12):
# the named paths' hierarchical pins do not exist, the worst paths below are named
# through instances.tsv instead (scripts/flows/layout/layout_report.py).
set paths [expr {[info exists spef] ? {} : [named_paths]}]
foreach path $paths {
  lassign $path name from to sentence
  set f [open $out/path_$name.txt w]
  puts $f "# $sentence"
  close $f
  report_checks -path_delay max -from $from -to $to -format full -digits 3 >> $out/path_$name.txt
}
report_checks -path_delay max -group_count 5 -format full_clock -digits 3 > $out/sta_worst_paths.txt
report_check_types -verbose -max_delay -recovery -removal -clock_gating_setup -clock_gating_hold \
  -min_pulse_width > $out/sta_checks.txt
check_setup -verbose -unconstrained_endpoints -no_clock -no_input_delay -no_output_delay \
  -multiple_clock -loops -generated_clocks > $out/sta_unconstrained.txt
report_clock_properties > $out/sta_clocks.txt
report_clock_skew -setup > $out/sta_skew.txt
report_pulse_width_checks -verbose > $out/sta_pulse_width.txt
