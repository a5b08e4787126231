# OpenSTA constraints of specular_ip_axi (the whole IP: the AXI4-Lite top, the register
# block and the synchronous device; docs/rtl_ip.md), sourced by scripts/flows/synthesis/sta.tcl:
# `constrain T` states its one clock and the bus's timing at clock period T (ns).
#
#   - aclk: rising at 0; every flip-flop of the IP (the AXI top's, the register block's,
#     the device's) is on its rising edge. No generated or gated clock.
#   - AXI inputs (every VALID, READY, address, data, strobe, the PROT fields) come from
#     the master's flip-flops on the same clock through the interconnect: input delay
#     T/2, half the period for the master and the wires, half for the IP. Why half: the
#     device's own inputs have 3T/4 (a quarter period left, scripts/flows/designs/
#     specular_device_sync/), but there they only load registers; here ARVALID and
#     ARADDR go through the register block's read decoder and the read handshake's
#     fan-out in the same cycle, and a quarter period would make that path, not the
#     device, set T_sta (39.39 ns: ARVALID -> do_read -> STATUS.CAUSE). A half period is
#     the usual budget of an AXI slave's SDC when nothing is known of the interconnect;
#     the gate-level testbench keeps it (inputs change at the falling edge,
#     rtl/tb/specular_ip_axi_gate_tb.v).
#   - aresetn (synchronous, as AXI's ARESETn is released) comes straight from the
#     system's reset synchroniser, a flip-flop on aclk: input delay 0, one whole period.
#     It fans out unbuffered to every flip-flop of the register block and the AXI top
#     (the flow does not buffer: abc -fast); at T/2 like the bus it alone would set T_sta
#     (30.08 ns, one INVX1 driving it all, 12.7 ns; docs/silicon.md).
#   - Outputs (every READY, B, R, done_irq) are flip-flops or one gate after them and are
#     read by the master at the next rising edge: output delay 0, one period.
# No multicycle path and no false path: every path is a single-cycle path of aclk (the
# device's results have three periods in the protocol, timed in one as for the device).
proc constrain {T} {
  set half [expr {$T / 2.0}]
  create_clock -name aclk -period $T -waveform [list 0 $half] [get_ports aclk]
  set_propagated_clock [all_clocks]
  set_input_delay -clock aclk $half \
    [get_ports {s_axi_awvalid s_axi_awaddr* s_axi_awprot* s_axi_wvalid s_axi_wdata*
                s_axi_wstrb* s_axi_bready s_axi_arvalid s_axi_araddr* s_axi_arprot* s_axi_rready}]
  set_input_delay -clock aclk 0 [get_ports aresetn]
  set_output_delay -clock aclk 0 \
    [get_ports {s_axi_awready s_axi_wready s_axi_bvalid s_axi_bresp* s_axi_arready
                s_axi_rvalid s_axi_rdata* s_axi_rresp* done_irq}]
}

# Named paths of the report: name, -from list, -to list (OpenSTA objects), a sentence.
# The AXI top's own flip-flops are the top level's cells (*/CLK without a hierarchy).
proc named_paths {} {
  set regs_d [get_pins regs/*/D]
  return [list \
    [list results [get_pins {device/reg2/*/CLK device/reg9/*/CLK}] $regs_d \
      "results: the device's register 9 or 2 -> multiplier 39 / ROM 38 -> multipliers 13-15 -> the register block's OUT_R/G/B, one period"] \
    [list pass2_select [get_pins device/cus/*/CLK] [get_pins device/reg9/*/D] \
      "pass 2 from select 36: the sequencer's pass2_q -> multiplexers 3, 4 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, one period (the bare synchronous device's worst path)"] \
    [list pass2_loop [get_pins device/reg9/*/CLK] [get_pins device/reg9/*/D] \
      "pass 2 loop: register 9 -> multiplexer 3 -> ROM 5 -> multiplier 6 -> inverter 7 -> adder 8 -> register 9, one period"] \
    [list operands [get_pins regs/*/CLK] [get_pins device/*/*/D] \
      "operands and START: the register block's COS, N, R, G, B and start pulse -> the device's registers 1, 2, 10-12 and sequencer, one period"] \
    [list axi_write [get_pins */CLK] $regs_d \
      "AXI write: the AXI top's held AW and W -> the register block's decoder, checks and registers, one period"] \
    [list axi_read [get_ports s_axi_araddr*] [get_pins */D] \
      "AXI read: ARADDR (input delay T/2) -> the register block's read decoder -> RDATA's flip-flops, half a period"] \
    [list axi_outputs [get_pins {*/CLK regs/*/CLK}] [get_ports {s_axi_* done_irq}] \
      "AXI outputs: the AXI top's and the register block's flip-flops -> READY, B, R, done_irq, read at the next rising edge, one period"] \
  ]
}
