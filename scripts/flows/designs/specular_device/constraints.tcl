# OpenSTA constraints of specular_device (Fig. 1/2 as drawn), sourced by
# scripts/flows/synthesis/sta.tcl: `constrain T` states the device's clocks and the protocol of
# spec section 3 at clock period T (ns). Per top: specular_device_sync brings its own.
#
# Clocks as they are (every command here was tried on Debian 12's OpenSTA 2.0.17):
#   - clk: pin 28, rising at 0 (the testbench's edges are T/2 later: the same relation).
#   - inverter 44's output (clock of 42, 43) and strobe 37 (clock of register 9) are not
#     declared: OpenSTA propagates clk through INVX1 44 (inverted) and through NANDs 45,
#     46, 47 (non-inverted at 37) and checks the gating inputs Q42, Q43 of NANDs 45, 46
#     as clock-gating checks. Register 9 is thus clocked at every rising clk edge plus the
#     real delay of 45 -> 47 (its two pulses of an operation are two of those edges).
#   - start (pin 27): a clock of period 2 T (back-to-back starts), rising with clk; it
#     clocks flip-flop 41 and register 1.
#   - loads (pins 30-33): a clock of period 2 T, high the quarter period before start.
# The paths from start and the loads are synchronous with clk (one origin).
proc constrain {T} {
  set half [expr {$T / 2.0}]
  set quarter [expr {$T / 4.0}]
  set period2 [expr {2.0 * $T}]
  create_clock -name clk -period $T -waveform [list 0 $half] [get_ports pin28_clk]
  create_clock -name start -period $period2 -waveform [list 0 $half] [get_ports pin27_start]
  create_clock -name load -period $period2 -waveform [list [expr {$period2 - $quarter}] $period2] \
    [get_ports {pin30_load_n pin31_load_r pin32_load_g pin33_load_b}]

  # The clock network's real delays (inverter 44, NANDs 45-47), not ideal clocks.
  set_propagated_clock [all_clocks]

  # Data a quarter period before its strobe (spec section 3): pin 17 before start, pins
  # 18, 21-23 before their loads.
  set_input_delay -clock start [expr {$period2 - $quarter}] [get_ports pin17_cos*]
  set_input_delay -clock load [expr {$period2 - $quarter}] \
    [get_ports {pin18_n* pin21_r* pin22_g* pin23_b*}]

  # Registers 2, 10-12 are written T/4 before start and read by pass 1 (at T after
  # start: 1.25 T later) and by pins 24-26 (at 2.5 T: 2.75 T later).
  set_multicycle_path -setup 2 -from [get_clocks load] -to [get_clocks clk]

  # Pins 24-26 are read at the rising edge of 35, which follows clk's falling edge
  # (2.5 T after start) through NAND 46: required at that falling edge, NAND 46's delay
  # is margin.
  set_output_delay -clock clk -clock_fall 0 [get_ports {pin24_r* pin25_g* pin26_b*}]

  # Static inputs: pins 19, 20 (wired constants of the constants policy), pin 34 (carry,
  # tied), the configuration inputs: set once for the device's life, never timed.
  set_false_path -from [get_ports {pin19_h* pin20_a* pin34_carry cfg_literal cfg_rom38_bank*}]
  # Reset (pin 29) is asynchronous and released while the device is idle (spec section 3).
  set_false_path -from [get_ports pin29_reset_n]
}

# Named paths of the report: name, -from list, -to list (OpenSTA objects), a sentence.
proc named_paths {} {
  set reg9_d [get_pins reg9/*/D]
  return [list \
    [list pass1 [get_pins reg1/*/CLK] $reg9_d \
      "pass 1: register 1 -> multiplexer 3 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, captured by strobe 37 at T after start"] \
    [list pass2_select [get_pins cu16/dff43.cell/CLK] $reg9_d \
      "pass 2 from select 36: flip-flop 43 (clk falling) -> multiplexers 3, 4 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, half a period"] \
    [list pass2_loop [get_pins reg9/*/CLK] $reg9_d \
      "pass 2 loop: register 9 -> multiplexer 3 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, one period"] \
    [list output [get_pins reg9/*/CLK] [get_ports {pin24_r* pin25_g* pin26_b*}] \
      "output: register 9 -> multiplier 39 -> multipliers 13-15 -> pins 24-26 before 35 rises, half a period"] \
    [list control_unit [get_pins cu16/*/CLK] [get_pins cu16/*/D] \
      "control unit: flip-flops 41 -> 42 -> 43 (inverter 44's clock)"] \
  ]
}
