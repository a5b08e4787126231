// Verilator's headers first: they define vl_time_stamp64() one way with SystemC's
// headers already seen and another without, and the model was compiled without them.
#include <verilated.h>
#include <verilated_vcd_c.h>

#include "Vspecular_device_cc.h"

#include "specular/twin/rtl_device.h"

#include <stdexcept>

#include "specular/arith.h"

namespace specular {

namespace {

/// The low `width` bits of a code, as Verilator's unsigned port types carry them.
template <class Port>
Port port_bits(code_t code, int width) {
  return static_cast<Port>(static_cast<std::uint64_t>(code) &
                           ((width >= 64) ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1));
}

/// True when `f` are the formats the model was verilated with (rtl/ parameters'
/// defaults, which are docs/design.md's: the default Widths).
bool default_formats(const Formats& f) {
  const Formats d{Widths{}};
  const auto same = [](const FixedFormat& a, const FixedFormat& b) {
    return a.is_signed == b.is_signed && a.int_bits == b.int_bits && a.frac_bits == b.frac_bits;
  };
  return same(f.cos, d.cos) && same(f.n, d.n) && same(f.rgb, d.rgb) && same(f.mux4, d.mux4) &&
         same(f.log2, d.log2) && same(f.reg9, d.reg9) && same(f.rom38, d.rom38) &&
         same(f.norm, d.norm) && same(f.out, d.out) &&
         f.widths.rom5_addr_bits == d.widths.rom5_addr_bits;
}

}  // namespace

/// The verilated model (plain C++, evaluated from this module's one process) and
/// Verilator's waveform writer.
struct RtlDevice::Verilated {
  VerilatedContext context;
  Vspecular_device_cc top{&context};
  std::unique_ptr<VerilatedVcdC> vcd;
  std::uint64_t last_eval_ps = 0;  ///< when the model was last evaluated
  bool evaluated = false;
};

RtlDevice::RtlDevice(sc_core::sc_module_name name, const Config& config, bool real_views)
    : sc_module(name), config_(config), formats_(config.widths) {
  if (!default_formats(formats_))
    throw std::invalid_argument(
        "the RTL twin is verilated at the default widths of docs/design.md; "
        "this Config asks for others (use --model pin or core for other widths)");
  if (real_views)
    throw std::invalid_argument(
        "the RTL twin has no real-valued views: its VCD holds the RTL's own nets as codes "
        "(waveforms/specular_rtl.gtkw shows them as real numbers)");
  SPECULAR_HAS_PROCESS(RtlDevice);
  rtl_ = std::make_unique<Verilated>();
  // The policies, tied off for the life of the device (configuration inputs).
  rtl_->top.cfg_literal = config.saturation == Saturation::literal;
  rtl_->top.cfg_rom38_bank = static_cast<unsigned>(config.normalisation);

  protocol_checker.start(pin27_start);
  protocol_checker.clk(pin28_clk);
  protocol_checker.reset_n(pin29_reset_n);
  protocol_checker.load_n30(pin30_load_n);
  protocol_checker.load_r31(pin31_load_r);
  protocol_checker.load_g32(pin32_load_g);
  protocol_checker.load_b33(pin33_load_b);
  protocol_checker.done35(pin35_done);
  protocol_checker.q41(q41);
  protocol_checker.q42(q42);
  protocol_checker.nand45(nand45);

  // One process: every input pin changed in a delta reaches the model together (a
  // strobe and its data, start and the clock keep their order at one instant), the
  // model settles in one eval, and the outputs change one delta later.
  SC_METHOD(evaluate);
  sensitive << pin17_cos << pin18_n << pin19_half << pin20_one << pin21_r << pin22_g << pin23_b
            << pin27_start << pin28_clk << pin29_reset_n << pin30_load_n << pin31_load_r
            << pin32_load_g << pin33_load_b << pin34_carry;
  // Outputs start as the netlist's do (35 high, NAND 45 high) until the first eval.
  pin35_done.initialize(true);
  nand45.write(true);
}

RtlDevice::~RtlDevice() = default;

void RtlDevice::evaluate() {
  const Formats& f = formats_;
  Verilated& v = *rtl_;
  Vspecular_device_cc& top = v.top;
  const std::uint64_t now_ps = sc_core::sc_time_stamp().value();
  // The waveform holds each instant's settled values: the state left by the last
  // evaluation at an earlier instant is dumped at that instant, before it changes.
  if (v.vcd && v.evaluated && now_ps > v.last_eval_ps) v.vcd->dump(v.last_eval_ps);
  top.pin17_cos = static_cast<std::uint32_t>(port_bits<std::uint64_t>(pin17_cos.read(), f.cos.width()));
  top.pin18_n = static_cast<std::uint16_t>(port_bits<std::uint64_t>(pin18_n.read(), f.n.width()));
  top.pin19_half = static_cast<std::uint16_t>(port_bits<std::uint64_t>(pin19_half.read(), f.mux4.width()));
  top.pin20_one = port_bits<std::uint64_t>(pin20_one.read(), f.reg9.width());
  top.pin21_r = static_cast<std::uint8_t>(port_bits<std::uint64_t>(pin21_r.read(), f.rgb.width()));
  top.pin22_g = static_cast<std::uint8_t>(port_bits<std::uint64_t>(pin22_g.read(), f.rgb.width()));
  top.pin23_b = static_cast<std::uint8_t>(port_bits<std::uint64_t>(pin23_b.read(), f.rgb.width()));
  top.pin27_start = pin27_start.read();
  top.pin28_clk = pin28_clk.read();
  top.pin29_reset_n = pin29_reset_n.read();
  top.pin30_load_n = pin30_load_n.read();
  top.pin31_load_r = pin31_load_r.read();
  top.pin32_load_g = pin32_load_g.read();
  top.pin33_load_b = pin33_load_b.read();
  top.pin34_carry = pin34_carry.read();
  top.eval();
  v.last_eval_ps = now_ps;
  v.evaluated = true;
  // Signed buses come back sign-extended from their width (arith::wrap).
  pin24_r.write(arith::wrap(f.out, static_cast<code_t>(top.pin24_r)));
  pin25_g.write(arith::wrap(f.out, static_cast<code_t>(top.pin25_g)));
  pin26_b.write(arith::wrap(f.out, static_cast<code_t>(top.pin26_b)));
  pin35_done.write(top.pin35_done);
  select36.write(top.obs_select36);
  write37.write(top.obs_write37);
  q41.write(top.obs_q41);
  q42.write(top.obs_q42);
  nand45.write(top.obs_nand45);
  reg1_q.write(static_cast<code_t>(top.obs_reg1_q));
  reg9_q.write(arith::wrap(f.reg9, static_cast<code_t>(top.obs_reg9_q)));
  rom38_k.write(static_cast<code_t>(top.obs_rom38_k));
  mul39_norm.write(arith::wrap(f.norm, static_cast<code_t>(top.obs_mul39_norm)));
}

void RtlDevice::open_vcd(const std::string& path) {
  vcd_path_ = path;
  rtl_->context.traceEverOn(true);
}

void RtlDevice::start_of_simulation() {
  if (vcd_path_.empty()) return;
  rtl_->vcd = std::make_unique<VerilatedVcdC>();
  rtl_->top.trace(rtl_->vcd.get(), 99);
  // SystemC's time resolution (1 ps by default) is the waveform's time unit.
  rtl_->vcd->set_time_resolution("1ps");
  rtl_->vcd->set_time_unit("1ps");
  rtl_->vcd->open(vcd_path_.c_str());
}

void RtlDevice::end_of_simulation() {
  if (!rtl_->vcd) return;
  if (rtl_->evaluated) rtl_->vcd->dump(rtl_->last_eval_ps);
  rtl_->vcd->close();
}

template class DeviceHarness<RtlDevice>;

}  // namespace specular
