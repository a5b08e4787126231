# OpenSTA constraints of any design variant's top behind the common ports
# (docs/design_space/flow.md, "Conventions (every variant follows them)"), sourced by scripts/flows/synthesis/sta.tcl when the top
# has no folder of its own: `constrain T` states its one clock and the protocol of
# rtl/tb/specular_variant_tb.v at clock period T (ns).
#
#   - clk: rising at 0; every flip-flop of a variant is on its rising edge.
#   - Inputs (start, reset_n, which is synchronous, cos, n, r, g, b) are levels presented
#     3T/4 after a rising edge and sampled at the next: input delay 3T/4.
#   - Outputs (ready, valid, lobe, out_r, out_g, out_b) are read at the next rising edge:
#     output delay 0, one period.
# No multicycle path and no false path: every path is a single-cycle path of clk (a
# variant that holds a value for several clocks is timed in one: conservative).
proc constrain {T} {
  set half [expr {$T / 2.0}]
  set three_quarters [expr {0.75 * $T}]
  create_clock -name clk -period $T -waveform [list 0 $half] [get_ports clk]
  set_propagated_clock [all_clocks]
  set_input_delay -clock clk $three_quarters \
    [get_ports {start reset_n cos[*] n[*] r[*] g[*] b[*]}]
  set_output_delay -clock clk 0 [get_ports {ready valid lobe[*] out_r[*] out_g[*] out_b[*]}]
}

# Named paths of the report (generic: by kind of endpoint): name, -from, -to, a sentence.
proc named_paths {} {
  set clocks [all_registers -clock_pins]
  set data [all_registers -data_pins]
  set inputs [get_ports {start reset_n cos[*] n[*] r[*] g[*] b[*]}]
  set outputs [get_ports {ready valid lobe[*] out_r[*] out_g[*] out_b[*]}]
  return [list \
    [list reg_to_reg $clocks $data \
      "register to register: the worst path between two flip-flops, one period"] \
    [list input_to_reg $inputs $data \
      "input to register: an input pin (3T/4 late) to a flip-flop, a quarter period"] \
    [list reg_to_output $clocks $outputs \
      "register to output: a flip-flop to an output pin, read at the next rising edge, one period"] \
    [list input_to_output $inputs $outputs \
      "input to output: a combinational path from an input pin to an output pin (none expected: ready is a function of state)"] \
  ]
}
