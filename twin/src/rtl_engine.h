// The drawn twin's protocol around one verilated model (rtl_cycle_model.cpp): a template
// over the class Verilator made — the general models at two width sets
// (Vspecular_device_fast, Vspecular_device_w20) and the specialised ones
// (Vspecular_device_fixed_*, twin/fixed/rtl_sync_fixed.cmake). Include after the
// verilated model's headers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <verilated.h>

#include "specular/arith.h"
#include "specular/rom38_banks.h"
#include "specular/twin/rtl_cycle_model.h"
#include "rom_loader.h"
#include "rtl_coverage.h"
#include "thread_context_guard.h"

namespace specular {

namespace rtl_detail {
inline std::uint64_t low_bits(code_t code, int width) {
  return static_cast<std::uint64_t>(code) & ((std::uint64_t{1} << width) - 1);
}
}  // namespace rtl_detail

/// What RtlCycleModel needs of a verilated device, whatever its widths.
class RtlCycleModel::Engine {
 public:
  virtual ~Engine() = default;
  virtual void reset() = 0;
  virtual void run_batch(const Operands* in, Result* out, double* cycles, std::size_t count) = 0;
  virtual std::uint64_t half_periods() const = 0;
  /// Whether the model was verilated for this one configuration (FIXED_CONFIG = 1).
  virtual bool fixed() const = 0;
};

/// Time counts in quarter periods (two per clock edge); n, R, G, B and their strobes
/// come a quarter period before a start, when they change.
/// `IsFixed`: Model is a specialised verilation (FIXED_CONFIG = 1; it ignores the
/// configuration pins written here).
template <class Model, bool IsFixed = false>
class VerilatedEngine final : public RtlCycleModel::Engine {
 public:
  VerilatedEngine(const Config& config, const Formats& formats)
      : formats_(formats), top_(&context_) {
    load_rom_words(*top_.rootp, formats);
    top_.cfg_literal = config.saturation == Saturation::literal;
    top_.cfg_rom38_bank = rom38_bank(config);
    top_.pin19_h = static_cast<std::uint32_t>(rtl_detail::low_bits(pin19_code(config), formats.mux4.width()));
    top_.pin20_a = rtl_detail::low_bits(pin20_code(config), formats.reg9.width());
    top_.pin34_carry = 1;
    top_.pin29_reset_n = 1;
    top_.pin28_clk = 0;
    top_.pin27_start = 0;
    top_.pin30_load_n = top_.pin31_load_r = top_.pin32_load_g = top_.pin33_load_b = 0;
    top_.eval();
    select36_ = top_.obs_select36;
    done35_ = top_.pin35_done;
  }
  ~VerilatedEngine() override {
    context_guard_.enter();  // the scopes unregister there (thread_context_guard.h)
    top_.final();
  }
  bool fixed() const override { return IsFixed; }

  void reset() override {
    top_.pin29_reset_n = 0;
    edge(true, false);
    edge(false, false);
    top_.pin29_reset_n = 1;
    top_.eval();
    loaded_ = false;
    pending_ = 0;
  }

  void run_batch(const Operands* in, Result* out, double* cycles, std::size_t count) override {
    out_ = out;
    cycles_ = cycles;
    pass1_seen_ = done_seen_ = started_ = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const Operands& op = in[i];
      const bool reload = !loaded_ || op.n != loaded_n_ || op.rgb != loaded_rgb_;
      // A reload waits for the operation in flight to finish (35 rises at its 5 T/2);
      // otherwise the next start comes with its rising edge at 2 T (pipelined).
      if (reload && pending_ != 0) finish();
      if (reload) {
        top_.pin18_n = static_cast<unsigned>(rtl_detail::low_bits(op.n, formats_.n.width()));
        top_.pin21_r = static_cast<unsigned>(rtl_detail::low_bits(op.rgb[0], formats_.rgb.width()));
        top_.pin22_g = static_cast<unsigned>(rtl_detail::low_bits(op.rgb[1], formats_.rgb.width()));
        top_.pin23_b = static_cast<unsigned>(rtl_detail::low_bits(op.rgb[2], formats_.rgb.width()));
        top_.pin30_load_n = top_.pin31_load_r = top_.pin32_load_g = top_.pin33_load_b = 1;
        quarter_ += 1;  // a quarter period before the start edge
        evaluate();
        quarter_ -= 1;
        loaded_ = true;
        loaded_n_ = op.n;
        loaded_rgb_ = op.rgb;
      }
      top_.pin30_load_n = top_.pin31_load_r = top_.pin32_load_g = top_.pin33_load_b = 0;
      top_.pin17_cos = static_cast<unsigned>(rtl_detail::low_bits(op.cos, formats_.cos.width()));
      start_quarter_[started_ % 2] = quarter_ + 2;  // the coming rising edge
      ++started_;
      ++pending_;
      edge(true, true);    // start: register 1 ← pin 17, Q41 ← 1 (and a previous pass 2)
      edge(false, false);  // Q42 ← 1 (and a previous operation's 35↑)
      edge(true, false);   // pass 1 into register 9
      edge(false, false);  // select 36 rises
    }
    if (pending_ != 0) finish();
    if (done_seen_ != count)
      throw std::logic_error("RTL twin: pin 35 rose " + std::to_string(done_seen_) + " times for " +
                             std::to_string(count) + " operations");
  }

  std::uint64_t half_periods() const override { return quarter_ / 2; }

 private:
  /// The operation in flight: pass 2 on the next rising edge, 35↑ on the falling one.
  void finish() {
    edge(true, false);
    edge(false, false);
  }

  /// One clock edge, half a period after the previous one; start (27) with it.
  void edge(bool clock, bool start) {
    top_.pin28_clk = clock;
    top_.pin27_start = start;
    quarter_ += 2;
    evaluate();
  }

  /// Evaluate, then sample as DeviceHarness's monitor does: register 1 and pass 1 at
  /// select 36↑, the results at 35↑ (and count the periods from start to 35↑).
  void evaluate() {
    top_.eval();
    const bool select36 = top_.obs_select36;
    const bool done35 = top_.pin35_done;
    if (select36 && !select36_ && out_ != nullptr && pass1_seen_ < started_) {
      Result& r = out_[pass1_seen_++];
      r.reg1 = static_cast<code_t>(top_.obs_reg1_q);
      r.reg9_pass1 = arith::wrap(formats_.reg9, static_cast<code_t>(top_.obs_reg9_q));
    }
    if (done35 && !done35_ && out_ != nullptr && done_seen_ < started_) {
      Result& r = out_[done_seen_];
      r.reg9_pass2 = arith::wrap(formats_.reg9, static_cast<code_t>(top_.obs_reg9_q));
      r.rom38_k = static_cast<code_t>(top_.obs_rom38_k);
      r.norm39 = arith::wrap(formats_.norm, static_cast<code_t>(top_.obs_mul39_norm));
      r.out = {arith::wrap(formats_.out, static_cast<code_t>(top_.pin24_r)),
               arith::wrap(formats_.out, static_cast<code_t>(top_.pin25_g)),
               arith::wrap(formats_.out, static_cast<code_t>(top_.pin26_b))};
      cycles_[done_seen_] = static_cast<double>(quarter_ - start_quarter_[done_seen_ % 2]) / 4.0;
      ++done_seen_;
      --pending_;
    }
    select36_ = select36;
    done35_ = done35;
  }

  Formats formats_;
  VerilatedContext context_;
  ThreadContextGuard context_guard_{context_};  // between the two: see there
  Model top_;
  RtlCoverageScope coverage_{context_};  // after the model: read before it goes
  std::uint64_t quarter_ = 0;
  bool select36_ = false;
  bool done35_ = true;
  bool loaded_ = false;
  code_t loaded_n_ = 0;
  std::array<code_t, 3> loaded_rgb_{};
  // The batch in flight: at most two operations overlap (a start every 2 T, 2.5 T each).
  Result* out_ = nullptr;
  double* cycles_ = nullptr;
  std::size_t pass1_seen_ = 0;
  std::size_t done_seen_ = 0;
  std::size_t started_ = 0;
  std::size_t pending_ = 0;
  std::uint64_t start_quarter_[2] = {0, 0};
};

}  // namespace specular
