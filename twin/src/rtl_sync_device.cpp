// Verilator's headers first: they define vl_time_stamp64() one way with SystemC's
// headers already seen and another without, and the model was compiled without them.
#include <verilated.h>
#include <verilated_vcd_c.h>

#include "Vspecular_device_sync_cc.h"

#include "specular/twin/rtl_sync_device.h"

#include <stdexcept>

#include "specular/arith.h"
#include "specular/rom38_banks.h"
#include "same_formats.h"

namespace specular {

/// The verilated synchronous device (plain C++, evaluated from this module's one
/// process) and Verilator's waveform writer: as RtlDevice's, other nets observed.
struct RtlSyncDevice::Verilated {
  /// The model's outputs after the last evaluation, as its port bits.
  struct Outputs {
    std::uint64_t pin24, pin25, pin26, reg9, reg1, rom38, norm, done35, select36, pass1;
  };
  /// The channels bound to the input pins (end_of_elaboration).
  struct Inputs {
    const sc_core::sc_signal_in_if<code_t>*pin17, *pin18, *pin19, *pin20, *pin21, *pin22, *pin23;
    const sc_core::sc_signal_in_if<bool>*pin27, *pin28, *pin29, *pin30, *pin31, *pin32, *pin33, *pin34;
  };
  VerilatedContext context;
  Vspecular_device_sync_cc top{&context};
  std::unique_ptr<VerilatedVcdC> vcd;
  std::uint64_t last_eval_ps = 0;  ///< when the model was last evaluated
  bool evaluated = false;
  Inputs inputs{};
  Outputs outputs{};
  bool outputs_valid = false;
};

RtlSyncDevice::RtlSyncDevice(sc_core::sc_module_name name, const Config& config, bool real_views)
    : DevicePins(name), config_(config), formats_(config.widths) {
  if (!same_formats(config.widths, Widths{}))
    throw std::invalid_argument(
        "the synchronous RTL twin is verilated at the default widths of docs/design.md; "
        "this Config asks for others (use --model pin or core for other widths)");
  if (real_views)
    throw std::invalid_argument(
        "the synchronous RTL twin has no real-valued views: its VCD holds the RTL's own nets "
        "as codes (waveforms/specular_rtl_sync.gtkw shows them as real numbers)");
  rtl_ = std::make_unique<Verilated>();
  // The policies, tied off for the life of the device (configuration inputs).
  rtl_->top.cfg_literal = config.saturation == Saturation::literal;
  rtl_->top.cfg_rom38_bank = rom38_bank(config);
  arith::Rom38Table check(formats_, config);  // a device the core refuses, the twin refuses too

  // 35 starts high (idle) until the first evaluation.
  pin35_done.initialize(true);
}

RtlSyncDevice::~RtlSyncDevice() = default;

void RtlSyncDevice::evaluate() {
  // The model runs at the default widths only (constructor): compile-time masks.
  using F = DefaultFormats;
  constexpr auto bits = [](code_t code, const FixedFormat& format) {
    return static_cast<std::uint64_t>(code) & ((std::uint64_t{1} << format.width()) - 1);
  };
  Verilated& v = *rtl_;
  Vspecular_device_sync_cc& top = v.top;
  if (v.vcd) {
    // The waveform holds each instant's settled values: the state left by the last
    // evaluation at an earlier instant is dumped at that instant, before it changes.
    const std::uint64_t now_ps = sc_core::sc_time_stamp().value();
    if (v.evaluated && now_ps > v.last_eval_ps) v.vcd->dump(v.last_eval_ps);
    v.last_eval_ps = now_ps;
    v.evaluated = true;
  }
  const Verilated::Inputs& in = v.inputs;
  top.pin17_cos = static_cast<std::uint32_t>(bits(in.pin17->read(), F::cos));
  top.pin18_n = static_cast<std::uint16_t>(bits(in.pin18->read(), F::n));
  top.pin19_h = static_cast<std::uint16_t>(bits(in.pin19->read(), F::mux4));
  top.pin20_a = bits(in.pin20->read(), F::reg9);
  top.pin21_r = static_cast<std::uint8_t>(bits(in.pin21->read(), F::rgb));
  top.pin22_g = static_cast<std::uint8_t>(bits(in.pin22->read(), F::rgb));
  top.pin23_b = static_cast<std::uint8_t>(bits(in.pin23->read(), F::rgb));
  top.pin27_start = in.pin27->read();
  top.pin28_clk = in.pin28->read();
  top.pin29_reset_n = in.pin29->read();
  top.pin30_load_n = in.pin30->read();
  top.pin31_load_r = in.pin31->read();
  top.pin32_load_g = in.pin32->read();
  top.pin33_load_b = in.pin33->read();
  top.pin34_carry = in.pin34->read();
  top.eval();
  // Only outputs whose bits changed go back to their pins (signed buses sign-extended
  // from their width): a write per output and evaluation would cost as much as the
  // evaluation itself (docs/performance.md).
  Verilated::Outputs& was = v.outputs;
  const bool all = !v.outputs_valid;
  v.outputs_valid = true;
  const auto update = [all](auto& last, auto now, auto write) {
    if (all || now != last) {
      last = now;
      write(now);
    }
  };
  update(was.pin24, top.pin24_r, [&](std::uint64_t x) { pin24_r.write(arith::wrap(F::out, static_cast<code_t>(x))); });
  update(was.pin25, top.pin25_g, [&](std::uint64_t x) { pin25_g.write(arith::wrap(F::out, static_cast<code_t>(x))); });
  update(was.pin26, top.pin26_b, [&](std::uint64_t x) { pin26_b.write(arith::wrap(F::out, static_cast<code_t>(x))); });
  update(was.reg9, top.obs_reg9_q, [&](std::uint64_t x) { reg9_q.write(arith::wrap(F::reg9, static_cast<code_t>(x))); });
  update(was.reg1, top.obs_reg1_q, [&](std::uint64_t x) { reg1_q.write(static_cast<code_t>(x)); });
  update(was.rom38, top.obs_rom38_k, [&](std::uint64_t x) { rom38_k.write(static_cast<code_t>(x)); });
  update(was.norm, top.obs_mul39_norm, [&](std::uint64_t x) { mul39_norm.write(arith::wrap(F::norm, static_cast<code_t>(x))); });
  update(was.done35, top.pin35_done, [&](std::uint64_t x) { pin35_done.write(x != 0); });
  update(was.select36, top.obs_select36, [&](std::uint64_t x) { select36.write(x != 0); });
  update(was.pass1, top.obs_pass1, [&](std::uint64_t x) { pass1.write(x != 0); });
}

void RtlSyncDevice::end_of_elaboration() {
  // The pins' channels, read directly on the hot path (an sc_in read checks its binding
  // every time).
  rtl_->inputs = {pin17_cos.operator->(), pin18_n.operator->(), pin19_h.operator->(),
                  pin20_a.operator->(), pin21_r.operator->(), pin22_g.operator->(),
                  pin23_b.operator->(), pin27_start.operator->(), pin28_clk.operator->(),
                  pin29_reset_n.operator->(), pin30_load_n.operator->(), pin31_load_r.operator->(),
                  pin32_load_g.operator->(), pin33_load_b.operator->(), pin34_carry.operator->()};
}

void RtlSyncDevice::before_end_of_elaboration() {
  SPECULAR_HAS_PROCESS(RtlSyncDevice);
  // One process, as in RtlDevice. Pins 17, 18 and 21–23 reach only the D inputs of
  // registers 1, 2 and 10–12: their change alone changes no net, so it is read at the
  // next evaluation rather than evaluated on its own — except when tracing, where the
  // waveform shows each pin when it changes. Start and the loads feed the sequencer's
  // and the registers' enables, which the waveform shows: they stay in the list.
  SC_METHOD(evaluate);
  sensitive << pin19_h << pin20_a << pin27_start << pin28_clk << pin29_reset_n
            << pin30_load_n << pin31_load_r << pin32_load_g << pin33_load_b << pin34_carry;
  if (!vcd_path_.empty()) sensitive << pin17_cos << pin18_n << pin21_r << pin22_g << pin23_b;
}

void RtlSyncDevice::open_vcd(const std::string& path) {
  if (sc_core::sc_get_status() != sc_core::SC_ELABORATION)
    throw std::logic_error("RtlSyncDevice::open_vcd must be called before the simulation starts");
  vcd_path_ = path;
  rtl_->context.traceEverOn(true);
}

void RtlSyncDevice::start_of_simulation() {
  if (vcd_path_.empty()) return;
  rtl_->vcd = std::make_unique<VerilatedVcdC>();
  rtl_->top.trace(rtl_->vcd.get(), 99);
  // SystemC's time resolution (1 ps by default) is the waveform's time unit.
  rtl_->vcd->set_time_resolution("1ps");
  rtl_->vcd->set_time_unit("1ps");
  rtl_->vcd->open(vcd_path_.c_str());
}

void RtlSyncDevice::end_of_simulation() {
  if (!rtl_->vcd) return;
  if (rtl_->evaluated) rtl_->vcd->dump(rtl_->last_eval_ps);
  rtl_->vcd->close();
}

template class DeviceHarness<RtlSyncDevice>;

}  // namespace specular
