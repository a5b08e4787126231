#include "specular/device.h"

namespace specular {

SpecularDevice::SpecularDevice(sc_core::sc_module_name name, const Config& config,
                               bool real_views)
    : DevicePins(name),
      config_(config),
      formats_(config.widths),
      rom5_table_(formats_),
      rom38_table_(formats_, config),
      mux3("mux3", formats_),
      mux4("mux4", formats_),
      rom5("rom5", rom5_table_),
      mul6("mul6", formats_),
      inv7("inv7", formats_),
      adder8("adder8", formats_, config.saturation),
      mul13("mul13", formats_),
      mul14("mul14", formats_),
      mul15("mul15", formats_),
      rom38("rom38", rom38_table_),
      mul39("mul39", formats_) {
  // Input registers: 1 is written by the start pin itself (spec §2).
  reg1.d(pin17_cos);   reg1.load(pin27_start);  reg1.q(reg1_q);
  reg2.d(pin18_n);     reg2.load(pin30_load_n); reg2.q(reg2_q);
  reg10.d(pin21_r);    reg10.load(pin31_load_r); reg10.q(reg10_q);
  reg11.d(pin22_g);    reg11.load(pin32_load_g); reg11.q(reg11_q);
  reg12.d(pin23_b);    reg12.load(pin33_load_b); reg12.q(reg12_q);

  // The two-pass loop: multiplexers → ROM 5 → multiplier 6 → inverter 7 → adder 8 → register 9.
  mux3.reg1(reg1_q);  mux3.reg9(reg9_q);  mux3.select36(select36);  mux3.address(mux3_address);
  mux4.reg2(reg2_q);  mux4.h19(pin19_h);  mux4.select36(select36);  mux4.operand(mux4_operand);
  rom5.address(mux3_address);  rom5.log2(rom5_log2);
  mul6.log2(rom5_log2);  mul6.operand(mux4_operand);  mul6.product(mul6_product);
  inv7.product(mul6_product);  inv7.inverted(inv7_inverted);
  adder8.a20(pin20_a);  adder8.inverted(inv7_inverted);  adder8.carry34(pin34_carry);
  adder8.sum(adder8_sum);
  reg9.d(adder8_sum);  reg9.load(write37);  reg9.q(reg9_q);

  // Normalisation and colour: ROM 38 → multiplier 39 → multipliers 13–15 → pins 24–26.
  rom38.reg2(reg2_q);  rom38.k(rom38_k);
  mul39.reg9(reg9_q);  mul39.k(rom38_k);  mul39.norm(mul39_norm);
  mul13.norm(mul39_norm);  mul13.intensity(reg10_q);  mul13.out(pin24_r);
  mul14.norm(mul39_norm);  mul14.intensity(reg11_q);  mul14.out(pin25_g);
  mul15.norm(mul39_norm);  mul15.intensity(reg12_q);  mul15.out(pin26_b);

  cu16.start(pin27_start);
  cu16.clk(pin28_clk);
  cu16.reset_n(pin29_reset_n);
  cu16.select36(select36);
  cu16.write37(write37);
  cu16.done35(pin35_done);

  // Observer only: reports protocol misuse as SC_REPORT_WARNING (report_ids.h).
  bind(protocol_checker, cu16.q41, cu16.q42, cu16.nand45_y);

  if (real_views) {
    // Real views only where a number reads better than a code and is not shown by
    // another view: cos λ, register 9 (1 − n·log2 cos λ, then A), K(n), K·A and the
    // outputs. ROM 5, multiplier 6 and adder 8 change several times per operation
    // (each pass and glitch); as doubles they cost more than half of the VCD's time
    // (docs/performance.md) and register 9's view shows adder 8 one write later.
    const std::pair<const bus_signal*, const FixedFormat*> views[] = {
        {&reg1_q, &formats_.cos},   {&reg9_q, &formats_.reg9},
        {&rom38_k, &formats_.rom38}, {&mul39_norm, &formats_.norm}};
    for (const auto& [bus, format] : views) {
      const std::string view_name = std::string(bus->basename()) + "_real";
      real_views_.push_back(std::make_unique<RealView>(view_name.c_str(), *format));
      real_views_.back()->code(*bus);
    }
    const std::pair<bus_out*, const char*> pins[] = {
        {&pin24_r, "pin24_r_real"}, {&pin25_g, "pin25_g_real"}, {&pin26_b, "pin26_b_real"}};
    for (const auto& [pin, view_name] : pins) {
      real_views_.push_back(std::make_unique<RealView>(view_name, formats_.out));
      real_views_.back()->code(*pin);
    }
  }
}

void SpecularDevice::trace(sc_core::sc_trace_file* file) const {
  const std::string scope = std::string(name()) + ".";
  const std::pair<const bus_signal*, const FixedFormat*> buses[] = {
      {&reg1_q, &formats_.cos},         {&reg2_q, &formats_.n},
      {&mux3_address, &formats_.reg9},  {&rom5_log2, &formats_.log2},
      {&mux4_operand, &formats_.mux4},  {&mul6_product, &formats_.reg9},
      {&inv7_inverted, &formats_.reg9}, {&adder8_sum, &formats_.reg9},
      {&reg9_q, &formats_.reg9},        {&reg10_q, &formats_.rgb},
      {&reg11_q, &formats_.rgb},        {&reg12_q, &formats_.rgb},
      {&rom38_k, &formats_.rom38},      {&mul39_norm, &formats_.norm}};
  for (const auto& [bus, format] : buses)
    trace_bus(file, *bus, *format, scope + bus->basename());
  sc_core::sc_trace(file, select36, scope + "select36");
  sc_core::sc_trace(file, write37, scope + "write37");
  for (const auto& view : real_views_)
    sc_core::sc_trace(file, view->value(), scope + view->basename());
  cu16.trace(file);
}

}  // namespace specular
