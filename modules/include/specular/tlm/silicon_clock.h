/// \file
/// The device's clock period in silicon, for the TLM targets' latency annotation: an SoC
/// simulation that wants real nanoseconds constructs a target with osu018_clock_period()
/// (docs/silicon/ip_tests.md, "The TLM targets in real nanoseconds").
#pragma once

#include <systemc>

namespace specular {

/// Clock period of specular_device mapped onto the OSU 0.18 um standard cells, in ns.
/// Derived from T_sta = 37.18 ns (scripts/flows/synthesis/silicon.sh: OpenSTA 2.0.17, osu018_stdcells.lib
/// typical corner 1.8 V 25 C, the ROM macros of scripts/flows/synthesis/rom_model.py): the worst
/// path is pass 2's, from flip-flop 43 (select 36, clocked on the falling edge through
/// inverter 44) through multiplexer 3, ROM 5, multiplier 6, inverter 7 and adder 8 into
/// register 9, 19.4 ns that must fit in half a period. Rounded up to the next 0.5 ns:
/// 37.5 ns (26.7 MHz; a result every 2 T = 75 ns streamed, 13.3 M results/s).
constexpr double kOsu018ClockPeriodNs = 37.5;

/// kOsu018ClockPeriodNs as an sc_time (a function: an sc_time needs the SystemC kernel,
/// which a namespace-scope constant would construct before sc_main).
inline sc_core::sc_time osu018_clock_period() {
  return sc_core::sc_time(kOsu018ClockPeriodNs, sc_core::SC_NS);
}

}  // namespace specular
