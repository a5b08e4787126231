// The floor of a pin-level measurement: a device with pins 17–35 that computes
// nothing and keeps only the spec's timing (select 36 at 1.5 T, 35 low at 2 T and high
// at 2.5 T after each start), so that DeviceHarness runs its protocol unchanged. What
// the bench measures with it is the cost of the kernel, the clock and the harness:
// no device under that harness can be faster.
#pragma once

#include <stdexcept>

#include "specular/core.h"
#include "specular/device_harness.h"
#include "specular/device_pins.h"
#include "specular/systemc.h"

namespace specular_bench {

class FloorDevice : public specular::DevicePins {
 public:
  specular::wire select36{"select36"};
  specular::bus_signal reg1_q{"reg1_q"};
  specular::bus_signal reg9_q{"reg9_q"};
  specular::bus_signal rom38_k{"rom38_k"};
  specular::bus_signal mul39_norm{"mul39_norm"};

  FloorDevice(sc_core::sc_module_name name, const specular::Config& config, bool /*real_views*/)
      : DevicePins(name), config_(config), formats_(config.widths) {
    SPECULAR_HAS_PROCESS(FloorDevice);
    SC_METHOD(on_start);
    sensitive << pin27_start.pos();
    dont_initialize();
    SC_METHOD(on_edge);
    sensitive << edges_;
    dont_initialize();
    pin35_done.initialize(true);
  }

  const specular::Formats& formats() const { return formats_; }
  specular::code_t constant_h19() const { return specular::pin19_code(config_); }
  specular::code_t constant_a20() const { return specular::pin20_code(config_); }
  void trace(sc_core::sc_trace_file*) const override {}

 private:
  void start_of_simulation() override {
    const auto* clock = dynamic_cast<const sc_core::sc_clock*>(pin28_clk.get_interface());
    if (clock == nullptr) throw std::logic_error("FloorDevice: pin 28 must be an sc_clock");
    period_ = clock->period();
  }
  // A start at t0: select 36 rises at t0 + 1.5 T, 35 falls at t0 + 2 T and rises at
  // t0 + 2.5 T (select 36 falls with it). An event queue, not an event: operations
  // overlap when starts come every 2 T, and their edges still come in that order.
  void on_start() {
    edges_.notify(period_ * 1.5);
    edges_.notify(period_ * 2);
    edges_.notify(period_ * 2.5);
  }
  void on_edge() {
    switch (phase_) {
      case 0: select36.write(true); break;
      case 1: pin35_done.write(false); break;
      default:
        pin35_done.write(true);
        select36.write(false);
    }
    phase_ = (phase_ + 1) % 3;
  }

  specular::Config config_;
  specular::Formats formats_;
  sc_core::sc_time period_;
  sc_core::sc_event_queue edges_{"edges"};
  int phase_ = 0;
};

}  // namespace specular_bench
