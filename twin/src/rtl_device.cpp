#include "specular/twin/rtl_device.h"

#include <stdexcept>

#include <verilated.h>
#include <verilated_vcd_sc.h>

#include "Vspecular_device_sc.h"
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

/// The verilated module, the signals of Verilator's port types between it and the
/// adapter's pins, and Verilator's waveform writer.
struct RtlDevice::Verilated {
  explicit Verilated(const char* name) : top(name) {}

  Vspecular_device_sc top;
  sc_core::sc_signal<std::uint32_t> pin17_cos{"rtl_pin17_cos"};
  sc_core::sc_signal<std::uint32_t> pin18_n{"rtl_pin18_n"};
  sc_core::sc_signal<std::uint32_t> pin19_half{"rtl_pin19_half"};
  sc_core::sc_signal<std::uint64_t> pin20_one{"rtl_pin20_one"};
  sc_core::sc_signal<std::uint32_t> pin21_r{"rtl_pin21_r"};
  sc_core::sc_signal<std::uint32_t> pin22_g{"rtl_pin22_g"};
  sc_core::sc_signal<std::uint32_t> pin23_b{"rtl_pin23_b"};
  sc_core::sc_signal<std::uint32_t> pin24_r{"rtl_pin24_r"};
  sc_core::sc_signal<std::uint32_t> pin25_g{"rtl_pin25_g"};
  sc_core::sc_signal<std::uint32_t> pin26_b{"rtl_pin26_b"};
  sc_core::sc_signal<bool> pin27_start{"rtl_pin27_start"};
  sc_core::sc_signal<bool> pin28_clk{"rtl_pin28_clk"};
  sc_core::sc_signal<bool> pin29_reset_n{"rtl_pin29_reset_n"};
  sc_core::sc_signal<bool> pin30_load_n{"rtl_pin30_load_n"};
  sc_core::sc_signal<bool> pin31_load_r{"rtl_pin31_load_r"};
  sc_core::sc_signal<bool> pin32_load_g{"rtl_pin32_load_g"};
  sc_core::sc_signal<bool> pin33_load_b{"rtl_pin33_load_b"};
  sc_core::sc_signal<bool> pin34_carry{"rtl_pin34_carry"};
  sc_core::sc_signal<bool> pin35_done{"rtl_pin35_done"};
  sc_core::sc_signal<bool> cfg_literal{"rtl_cfg_literal"};
  sc_core::sc_signal<std::uint32_t> cfg_rom38_bank{"rtl_cfg_rom38_bank"};
  sc_core::sc_signal<bool> obs_select36{"rtl_obs_select36"};
  sc_core::sc_signal<bool> obs_write37{"rtl_obs_write37"};
  sc_core::sc_signal<bool> obs_q41{"rtl_obs_q41"};
  sc_core::sc_signal<bool> obs_q42{"rtl_obs_q42"};
  sc_core::sc_signal<bool> obs_nand45{"rtl_obs_nand45"};
  sc_core::sc_signal<std::uint32_t> obs_reg1_q{"rtl_obs_reg1_q"};
  sc_core::sc_signal<std::uint64_t> obs_reg9_q{"rtl_obs_reg9_q"};
  sc_core::sc_signal<std::uint32_t> obs_rom38_k{"rtl_obs_rom38_k"};
  sc_core::sc_signal<std::uint32_t> obs_mul39_norm{"rtl_obs_mul39_norm"};
  std::unique_ptr<VerilatedVcdSc> vcd;
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
  rtl_ = std::make_unique<Verilated>("rtl");
  Verilated& v = *rtl_;
  Vspecular_device_sc& top = v.top;
  top.pin17_cos(v.pin17_cos);
  top.pin18_n(v.pin18_n);
  top.pin19_half(v.pin19_half);
  top.pin20_one(v.pin20_one);
  top.pin21_r(v.pin21_r);
  top.pin22_g(v.pin22_g);
  top.pin23_b(v.pin23_b);
  top.pin24_r(v.pin24_r);
  top.pin25_g(v.pin25_g);
  top.pin26_b(v.pin26_b);
  top.pin27_start(v.pin27_start);
  top.pin28_clk(v.pin28_clk);
  top.pin29_reset_n(v.pin29_reset_n);
  top.pin30_load_n(v.pin30_load_n);
  top.pin31_load_r(v.pin31_load_r);
  top.pin32_load_g(v.pin32_load_g);
  top.pin33_load_b(v.pin33_load_b);
  top.pin34_carry(v.pin34_carry);
  top.pin35_done(v.pin35_done);
  top.cfg_literal(v.cfg_literal);
  top.cfg_rom38_bank(v.cfg_rom38_bank);
  top.obs_select36(v.obs_select36);
  top.obs_write37(v.obs_write37);
  top.obs_q41(v.obs_q41);
  top.obs_q42(v.obs_q42);
  top.obs_nand45(v.obs_nand45);
  top.obs_reg1_q(v.obs_reg1_q);
  top.obs_reg9_q(v.obs_reg9_q);
  top.obs_rom38_k(v.obs_rom38_k);
  top.obs_mul39_norm(v.obs_mul39_norm);
  // The policies, tied off for the life of the device (configuration inputs).
  v.cfg_literal.write(config.saturation == Saturation::literal);
  v.cfg_rom38_bank.write(static_cast<std::uint32_t>(config.normalisation));

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

  SC_METHOD(drive_inputs);
  sensitive << pin17_cos << pin18_n << pin19_half << pin20_one << pin21_r << pin22_g << pin23_b
            << pin27_start << pin28_clk << pin29_reset_n << pin30_load_n << pin31_load_r
            << pin32_load_g << pin33_load_b << pin34_carry;
  SC_METHOD(read_outputs);
  sensitive << v.pin24_r << v.pin25_g << v.pin26_b << v.pin35_done << v.obs_select36
            << v.obs_write37 << v.obs_q41 << v.obs_q42 << v.obs_nand45 << v.obs_reg1_q
            << v.obs_reg9_q << v.obs_rom38_k << v.obs_mul39_norm;
  // Outputs start as the netlist's do (35 high, AND 40 idle high): the first
  // read_outputs runs with the model's first evaluation.
  pin35_done.initialize(true);
  nand45.write(true);
}

RtlDevice::~RtlDevice() = default;

void RtlDevice::drive_inputs() {
  const Formats& f = formats_;
  Verilated& v = *rtl_;
  v.pin17_cos.write(port_bits<std::uint32_t>(pin17_cos.read(), f.cos.width()));
  v.pin18_n.write(port_bits<std::uint32_t>(pin18_n.read(), f.n.width()));
  v.pin19_half.write(port_bits<std::uint32_t>(pin19_half.read(), f.mux4.width()));
  v.pin20_one.write(port_bits<std::uint64_t>(pin20_one.read(), f.reg9.width()));
  v.pin21_r.write(port_bits<std::uint32_t>(pin21_r.read(), f.rgb.width()));
  v.pin22_g.write(port_bits<std::uint32_t>(pin22_g.read(), f.rgb.width()));
  v.pin23_b.write(port_bits<std::uint32_t>(pin23_b.read(), f.rgb.width()));
  v.pin27_start.write(pin27_start.read());
  v.pin28_clk.write(pin28_clk.read());
  v.pin29_reset_n.write(pin29_reset_n.read());
  v.pin30_load_n.write(pin30_load_n.read());
  v.pin31_load_r.write(pin31_load_r.read());
  v.pin32_load_g.write(pin32_load_g.read());
  v.pin33_load_b.write(pin33_load_b.read());
  v.pin34_carry.write(pin34_carry.read());
}

void RtlDevice::read_outputs() {
  const Formats& f = formats_;
  const Verilated& v = *rtl_;
  // Signed buses come back sign-extended from their width (arith::wrap).
  pin24_r.write(arith::wrap(f.out, static_cast<code_t>(v.pin24_r.read())));
  pin25_g.write(arith::wrap(f.out, static_cast<code_t>(v.pin25_g.read())));
  pin26_b.write(arith::wrap(f.out, static_cast<code_t>(v.pin26_b.read())));
  pin35_done.write(v.pin35_done.read());
  select36.write(v.obs_select36.read());
  write37.write(v.obs_write37.read());
  q41.write(v.obs_q41.read());
  q42.write(v.obs_q42.read());
  nand45.write(v.obs_nand45.read());
  reg1_q.write(static_cast<code_t>(v.obs_reg1_q.read()));
  reg9_q.write(arith::wrap(f.reg9, static_cast<code_t>(v.obs_reg9_q.read())));
  rom38_k.write(static_cast<code_t>(v.obs_rom38_k.read()));
  mul39_norm.write(arith::wrap(f.norm, static_cast<code_t>(v.obs_mul39_norm.read())));
}

void RtlDevice::open_vcd(const std::string& path) {
  vcd_path_ = path;
  ::Verilated::traceEverOn(true);
}

void RtlDevice::start_of_simulation() {
  if (vcd_path_.empty()) return;
  rtl_->vcd = std::make_unique<VerilatedVcdSc>();
  rtl_->top.trace(rtl_->vcd.get(), 99);
  rtl_->vcd->open(vcd_path_.c_str());
}

void RtlDevice::end_of_simulation() {
  if (rtl_->vcd) rtl_->vcd->close();
}

template class DeviceHarness<RtlDevice>;

}  // namespace specular
