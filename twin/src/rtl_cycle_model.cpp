#include "specular/twin/rtl_cycle_model.h"

#include <stdexcept>

#include <verilated.h>

#include "Vspecular_device_fast.h"
#include "Vspecular_device_fast___024root.h"
#include "Vspecular_device_w20.h"
#include "Vspecular_device_w20___024root.h"
#include "rtl_engine.h"
#include "rtl_sync_fixed.h"
#include "same_formats.h"

namespace specular {

Widths rtl_alternate_widths() {
  Widths w;
  w.rom5_word_bits = 20;
  w.reg9_frac_bits = 16;
  return w;
}

RtlCycleModel::RtlCycleModel(const Config& config, bool allow_fixed) : config_(config) {
  const Formats formats(config.widths);
  arith::Rom38Table check(formats, config);  // a device the core refuses, the twin refuses too
  const RtlSyncFixedModel* fixed = allow_fixed ? rtl_sync_fixed_model(config) : nullptr;
  if (fixed != nullptr)
    engine_ = fixed->make_drawn_engine(config);
  else if (same_formats(config.widths, Widths{}))
    engine_ = std::make_unique<VerilatedEngine<Vspecular_device_fast>>(config, formats);
  else if (same_formats(config.widths, rtl_alternate_widths()))
    engine_ = std::make_unique<VerilatedEngine<Vspecular_device_w20>>(config, formats);
  else
    throw std::invalid_argument(
        "the RTL twin is verilated at two width sets only: the defaults of docs/design.md "
        "and rtl_alternate_widths() (ROM 5 word 20 bits, register 9 S14.16)");
}

RtlCycleModel::~RtlCycleModel() = default;

void RtlCycleModel::reset() { engine_->reset(); }

Result RtlCycleModel::run(const Operands& in) {
  std::vector<Result> out;
  run_batch({in}, out);
  return out.front();
}

void RtlCycleModel::run_batch(const std::vector<Operands>& in, std::vector<Result>& out) {
  out.assign(in.size(), Result{});
  cycles_.assign(in.size(), 0.0);
  engine_->run_batch(in.data(), out.data(), cycles_.data(), in.size());
}

std::uint64_t RtlCycleModel::half_periods() const { return engine_->half_periods(); }

bool RtlCycleModel::fixed() const { return engine_->fixed(); }

}  // namespace specular
