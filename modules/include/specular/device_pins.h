/// \file
/// Pins 17–35 of the device (spec §2), once for every device that has them: the SystemC
/// netlist (SpecularDevice), the RTL twin (RtlDevice, twin/) and the bench's floor
/// (bench/floor_device.h). DeviceHarness drives any of them.
#pragma once

#include "specular/protocol_checker.h"
#include "specular/systemc.h"

namespace specular {

/// The device's ports: pins 17–35 of Fig. 1 with the spec's numbers. A device derives
/// from it and binds them to its blocks. Formats: Formats (format.h), U1.16 cos, U10 n,
/// U8 R, G, B in and S18.13 out by default.
class DevicePins : public sc_core::sc_module {
 public:
  bus_in pin17_cos{"pin17_cos"};           ///< cos λ code → register 1 (U1.16)
  bus_in pin18_n{"pin18_n"};               ///< n code → register 2 (1..1000)
  bus_in pin19_h{"pin19_h"};               ///< h: ½ under the patent's constants
  bus_in pin20_a{"pin20_a"};               ///< a: 1.0 under the patent's constants
  bus_in pin21_r{"pin21_r"};               ///< R intensity → register 10 (U8)
  bus_in pin22_g{"pin22_g"};               ///< G intensity → register 11 (U8)
  bus_in pin23_b{"pin23_b"};               ///< B intensity → register 12 (U8)
  bus_out pin24_r{"pin24_r"};              ///< specular R: K·A·R from multiplier 13 (S18.13)
  bus_out pin25_g{"pin25_g"};              ///< specular G: K·A·G from multiplier 14 (S18.13)
  bus_out pin26_b{"pin26_b"};              ///< specular B: K·A·B from multiplier 15 (S18.13)
  wire_in pin27_start{"pin27_start"};      ///< write register 1 and start
  wire_in pin28_clk{"pin28_clk"};          ///< reference clock
  wire_in pin29_reset_n{"pin29_reset_n"};  ///< reset the control unit, active low
  wire_in pin30_load_n{"pin30_load_n"};    ///< write register 2
  wire_in pin31_load_r{"pin31_load_r"};    ///< write register 10
  wire_in pin32_load_g{"pin32_load_g"};    ///< write register 11
  wire_in pin33_load_b{"pin33_load_b"};    ///< write register 12
  wire_in pin34_carry{"pin34_carry"};      ///< adder 8 carry-in, tied to 1
  wire_out pin35_done{"pin35_done"};       ///< done: active-low pulse, rises when results are valid

 protected:
  /// Names the module; only a device deriving from DevicePins constructs it.
  explicit DevicePins(sc_core::sc_module_name name) : sc_module(name) {}

  /// Binds a protocol checker to these pins and to control unit 16's flip-flops 41,
  /// 42 and NAND 45, wherever the device keeps them.
  void bind(ProtocolChecker& checker, const wire& q41, const wire& q42, const wire& nand45) {
    checker.start(pin27_start);
    checker.clk(pin28_clk);
    checker.reset_n(pin29_reset_n);
    checker.load_n30(pin30_load_n);
    checker.load_r31(pin31_load_r);
    checker.load_g32(pin32_load_g);
    checker.load_b33(pin33_load_b);
    checker.done35(pin35_done);
    checker.q41(q41);
    checker.q42(q42);
    checker.nand45(nand45);
  }
};

}  // namespace specular
