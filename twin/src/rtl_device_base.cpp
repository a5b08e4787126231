#include "rtl_model.h"  // Verilator's headers first (see there)

#include <stdexcept>

#include "same_formats.h"

namespace specular {

RtlDeviceBase::RtlDeviceBase(sc_core::sc_module_name name, const Config& config,
                             bool real_views, const Variant& variant)
    : DevicePins(name), class_name_(variant.class_name), config_(config),
      formats_(config.widths) {
  const std::string twin = variant.twin_name;
  if (!same_formats(config.widths, Widths{}))
    throw std::invalid_argument(
        "the " + twin + " is verilated at the default widths of docs/design.md; "
        "this Config asks for others (use --model pin or core for other widths)");
  if (real_views)
    throw std::invalid_argument(
        "the " + twin + " has no real-valued views: its VCD holds the RTL's own nets as codes "
        "(" + variant.gtkw + " shows them as real numbers)");
  rtl_ = variant.make_model(config);
  make_model_ = variant.make_model;
  make_fst_model_ = variant.make_fst_model;
  arith::Rom38Table check(formats_, config);  // a device the core refuses, the twin refuses too

  // Done (35) starts high (idle), as the netlist's does, until the first evaluation.
  pin35_done.initialize(true);
}

RtlDeviceBase::~RtlDeviceBase() = default;

void RtlDeviceBase::evaluate() {
  Verilated& v = *rtl_;
  if (v.writing()) {
    // The waveform holds each instant's settled values: the state left by the last
    // evaluation at an earlier instant is dumped at that instant, before it changes.
    const std::uint64_t now_ps = sc_core::sc_time_stamp().value();
    if (v.evaluated && now_ps > v.last_eval_ps) v.dump(v.last_eval_ps);
    v.last_eval_ps = now_ps;
    v.evaluated = true;
  }
  v.evaluate(*this);
}

void RtlDeviceBase::end_of_elaboration() {
  // The pins' channels, read directly on the hot path (an sc_in read checks its binding
  // every time).
  rtl_->inputs = {pin17_cos.operator->(), pin18_n.operator->(), pin19_h.operator->(),
                  pin20_a.operator->(), pin21_r.operator->(), pin22_g.operator->(),
                  pin23_b.operator->(), pin27_start.operator->(), pin28_clk.operator->(),
                  pin29_reset_n.operator->(), pin30_load_n.operator->(), pin31_load_r.operator->(),
                  pin32_load_g.operator->(), pin33_load_b.operator->(), pin34_carry.operator->()};
}

void RtlDeviceBase::before_end_of_elaboration() {
  SPECULAR_HAS_PROCESS(RtlDeviceBase);
  // One process: every input pin changed in a delta reaches the model together (a
  // strobe and its data, start and the clock keep their order at one instant), the
  // model settles in one eval, and the outputs change one delta later. Pins 17, 18
  // and 21–23 reach only the D inputs of registers 1, 2 and 10–12: their change alone
  // changes no net, so it is read at the next evaluation (their strobe's edge; the
  // clock's edge in the synchronous variant) rather than evaluated on its own — except
  // when tracing, where the waveform shows each pin when it changes. In the synchronous
  // variant start and the loads feed the sequencer's and the registers' enables, which
  // the waveform shows: they stay in the list too. Declared here, once open_vcd() could
  // have been called.
  SC_METHOD(evaluate);
  sensitive << pin19_h << pin20_a << pin27_start << pin28_clk << pin29_reset_n
            << pin30_load_n << pin31_load_r << pin32_load_g << pin33_load_b << pin34_carry;
  if (traceable_) sensitive << pin17_cos << pin18_n << pin21_r << pin22_g << pin23_b;
}

void RtlDeviceBase::allow_tracing(bool fst) {
  if (sc_core::sc_get_status() != sc_core::SC_ELABORATION)
    throw std::logic_error(std::string(class_name_) +
                           "::allow_tracing must be called before the simulation starts");
  // ---- FST (issue 27): the model verilated with --trace-fst replaces the VCD one
  // before it has run (its policies tied off again; the pins' channels are taken at
  // end_of_elaboration, after this).
  if (fst != rtl_->fst()) rtl_ = fst ? make_fst_model_(config_) : make_model_(config_);
  traceable_ = true;
  rtl_->context.traceEverOn(true);
}

namespace {
bool fst_name(const std::string& path) {
  return path.size() >= 4 && path.compare(path.size() - 4, 4, ".fst") == 0;
}
}  // namespace

void RtlDeviceBase::open_vcd(const std::string& path) {
  if (sc_core::sc_get_status() == sc_core::SC_ELABORATION) {
    vcd_path_ = path;
    allow_tracing(fst_name(path));
    return;
  }
  if (!traceable_ || rtl_->writing())
    throw std::logic_error(std::string(class_name_) +
                           "::open_vcd during the simulation needs allow_tracing() before it "
                           "and no file open");
  if (fst_name(path) != rtl_->fst())
    throw std::logic_error(std::string(class_name_) + "::open_vcd('" + path + "'): the model " +
                           "writes " + (rtl_->fst() ? "FST" : "VCD") +
                           " (allow_tracing(" + (rtl_->fst() ? "true" : "false") +
                           ") chose it before the simulation)");
  open_writer(path);
  // The state the last evaluation left is this instant's: it is dumped here, at the
  // next evaluation at a later instant (evaluate()).
  rtl_->last_eval_ps = sc_core::sc_time_stamp().value();
  rtl_->evaluated = true;
}

void RtlDeviceBase::open_writer(const std::string& path) { rtl_->open_writer(path); }

void RtlDeviceBase::close_vcd() {
  if (!rtl_->writing()) return;
  if (rtl_->evaluated) rtl_->dump(rtl_->last_eval_ps);
  rtl_->close_writer();
  rtl_->evaluated = false;
}

void RtlDeviceBase::start_of_simulation() {
  if (!vcd_path_.empty()) open_writer(vcd_path_);
}

void RtlDeviceBase::end_of_simulation() { close_vcd(); }

}  // namespace specular
