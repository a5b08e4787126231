# OpenSTA constraints of specular_device_sync (the synchronous variant, docs/rtl.md),
# sourced by scripts/flows/synthesis/sta.tcl: `constrain T` states its one clock and its
# protocol at clock period T (ns).
#
#   - clk: pin 28, rising at 0; every flip-flop of the device is on its rising edge.
#   - Inputs are levels sampled at a rising edge and presented a quarter period before
#     it (start 27, pin 17, pins 18, 21-23 with their loads 30-33, reset 29, which is
#     synchronous): input delay 3T/4.
#   - Pins 19, 20, 34 and the configuration inputs are constant for the device's life;
#     they are timed anyway, as inputs that change a whole period before the edge
#     (input delay 0), so that no path of the device is left untimed.
#   - Outputs (pins 24-26, 35 and the observation outputs) are registered or decoded from
#     registers and read at the next rising edge: output delay 0, one period.
# No multicycle path and no false path: every path is a single-cycle path of clk (the
# register 2, 10-12 -> pins 24-26 paths have three periods in the protocol; timing them
# in one is conservative).
proc constrain {T} {
  set half [expr {$T / 2.0}]
  set three_quarters [expr {0.75 * $T}]
  create_clock -name clk -period $T -waveform [list 0 $half] [get_ports pin28_clk]
  set_propagated_clock [all_clocks]
  set_input_delay -clock clk $three_quarters \
    [get_ports {pin17_cos* pin18_n* pin21_r* pin22_g* pin23_b* pin27_start pin29_reset_n
                pin30_load_n pin31_load_r pin32_load_g pin33_load_b}]
  set_input_delay -clock clk 0 [get_ports {pin19_h* pin20_a* pin34_carry cfg_literal cfg_rom38_bank*}]
  set_output_delay -clock clk 0 [get_ports {pin24_r* pin25_g* pin26_b* pin35_done obs_*}]
}

# Named paths of the report: name, -from list, -to list (OpenSTA objects), a sentence.
proc named_paths {} {
  set reg9_d [get_pins reg9/*/D]
  return [list \
    [list pass1 [get_pins reg1/*/CLK] $reg9_d \
      "pass 1: register 1 -> multiplexer 3 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, one period"] \
    [list pass2_select [get_pins cus/*/CLK] $reg9_d \
      "pass 2 from select 36: the sequencer's pass2_q -> multiplexers 3, 4 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, one period"] \
    [list pass2_loop [get_pins reg9/*/CLK] $reg9_d \
      "pass 2 loop: register 9 -> multiplexer 3 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, one period"] \
    [list output [get_pins reg9/*/CLK] [get_ports {pin24_r* pin25_g* pin26_b*}] \
      "output: register 9 -> multiplier 39 -> multipliers 13-15 -> pins 24-26, read at the next rising edge, one period"] \
    [list control_unit [get_pins cus/*/CLK] [get_pins cus/*/D] \
      "control unit: the sequencer's flip-flops (pass1_q -> pass2_q, done_q)"] \
  ]
}
