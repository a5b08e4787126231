// The synchronous variant's protocol around one verilated model (rtl_sync_cycle_model.cpp):
// a template over the class Verilator made, so the general model
// (Vspecular_device_sync_fast) and each specialised one (Vspecular_device_sync_fixed_*,
// twin/fixed/rtl_sync_fixed.cmake) are clocked by the same code. Include after the
// verilated model's headers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include <verilated.h>

#include "specular/arith.h"
#include "specular/rom38_banks.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#include "rom_loader.h"
#include "rtl_coverage.h"
#include "thread_context_guard.h"
#include "verilated_clock.h"

namespace specular {

/// What RtlSyncCycleModel calls: one verilated model and its protocol.
class RtlSyncCycleModel::Engine {
 public:
  virtual ~Engine() = default;
  virtual void reset() = 0;
  /// `cycles` may be null (the bench's loop).
  virtual void run_batch(const Operands* in, Result* out, double* cycles, std::size_t count) = 0;
  virtual std::uint64_t half_periods() const = 0;
  /// Whether the model was verilated for this one configuration (FIXED_CONFIG = 1).
  virtual bool fixed() const = 0;
};

namespace rtl_sync_detail {
inline std::uint64_t low_bits(code_t code, int width) {
  return static_cast<std::uint64_t>(code) & ((std::uint64_t{1} << width) - 1);
}
}  // namespace rtl_sync_detail

/// The verilated synchronous device and its protocol. Inputs are levels sampled at
/// the rising edge: they are written between edges without an evaluation of their
/// own (nothing in the device reacts to them before the edge), so a clock period costs
/// two evaluations, the rising edge and the falling one Verilator needs to see the
/// next rising edge.
/// `IsFixed`: Top is a specialised verilation (FIXED_CONFIG = 1). Default widths only
/// (RtlSyncCycleModel's constructor): the formats are compile-time constants.
template <class Top, bool IsFixed>
class SyncEngine final : public RtlSyncCycleModel::Engine {
  using F = DefaultFormats;

 public:
  explicit SyncEngine(const Config& config) : formats_(config.widths), top_(&context_) {
    load_rom_words(*top_.rootp, formats_);
    top_.cfg_literal = config.saturation == Saturation::literal;
    top_.cfg_rom38_bank = rom38_bank(config);
    top_.pin19_h = static_cast<std::uint32_t>(rtl_sync_detail::low_bits(pin19_code(config), F::mux4.width()));
    top_.pin20_a = rtl_sync_detail::low_bits(pin20_code(config), F::reg9.width());
    top_.pin34_carry = 1;
    top_.pin29_reset_n = 1;
    top_.pin28_clk = 0;
    top_.pin27_start = 0;
    top_.pin30_load_n = top_.pin31_load_r = top_.pin32_load_g = top_.pin33_load_b = 0;
    top_.eval();
  }
  ~SyncEngine() override {
    // The model's scopes unregister from the thread's current context when destroyed
    // (Verilator 5.006, VerilatedScope::~VerilatedScope): make it this model's, not that
    // of another model made later and perhaps destroyed already (thread_context_guard.h).
    context_guard_.enter();
    top_.final();
  }

  void reset() override {
    top_.pin29_reset_n = 0;
    rise();
    fall();
    top_.pin29_reset_n = 1;
    loaded_ = false;
    in_flight_ = false;
  }

    void run_batch(const Operands* in, Result* out, double* cycles, std::size_t count) override {
    std::size_t done = 0;
    const auto collect = [&](std::size_t index) {
      Result& r = out[index];
      r.reg9_pass2 = arith::wrap(F::reg9, static_cast<code_t>(top_.obs_reg9_q));
      r.rom38_k = static_cast<code_t>(top_.obs_rom38_k);
      r.norm39 = arith::wrap(F::norm, static_cast<code_t>(top_.obs_mul39_norm));
      r.out = {arith::wrap(F::out, static_cast<code_t>(top_.pin24_r)),
               arith::wrap(F::out, static_cast<code_t>(top_.pin25_g)),
               arith::wrap(F::out, static_cast<code_t>(top_.pin26_b))};
      if (cycles != nullptr) cycles[index] = static_cast<double>(edges_ - start_edge_[index % 2]) / 2.0;
      ++done;
    };
    for (std::size_t i = 0; i < count; ++i) {
      const Operands& op = in[i];
      const bool reload = !loaded_ || op.n != loaded_n_ || op.rgb != loaded_rgb_;
      // A reload waits until the operation in flight has shown its result (35↑ at its
      // 2 T, held one period): the loads would change pins 24-26 under it.
      if (reload && in_flight_) finish(collect, done);
      // A quarter period before the start edge: start, pin 17 and (reload) the loads.
      top_.pin27_start = 1;
      top_.pin17_cos = static_cast<std::uint32_t>(rtl_sync_detail::low_bits(op.cos, F::cos.width()));
      if (reload) {
        top_.pin18_n = static_cast<std::uint16_t>(rtl_sync_detail::low_bits(op.n, F::n.width()));
        top_.pin21_r = static_cast<std::uint8_t>(rtl_sync_detail::low_bits(op.rgb[0], F::rgb.width()));
        top_.pin22_g = static_cast<std::uint8_t>(rtl_sync_detail::low_bits(op.rgb[1], F::rgb.width()));
        top_.pin23_b = static_cast<std::uint8_t>(rtl_sync_detail::low_bits(op.rgb[2], F::rgb.width()));
        top_.pin30_load_n = top_.pin31_load_r = top_.pin32_load_g = top_.pin33_load_b = 1;
        loaded_ = true;
        loaded_n_ = op.n;
        loaded_rgb_ = op.rgb;
      }
      start_edge_[i % 2] = edges_ + 1;
      rise();  // start edge: register 1, loads; the previous operation's pass 2 and 35↑
      if (in_flight_) {
        expect_done_rose(done);
        collect(done);
      }
      // A quarter period after it: start and the loads fall.
      top_.pin27_start = 0;
      top_.pin30_load_n = top_.pin31_load_r = top_.pin32_load_g = top_.pin33_load_b = 0;
      fall();
      rise();  // pass 1 into register 9, select 36 rises
      if (!top_.obs_select36 || top_.pin35_done)
        throw std::logic_error("RTL sync twin: select 36 low or 35 high 1 T after start " +
                               std::to_string(i));
      out[i].reg1 = static_cast<code_t>(top_.obs_reg1_q);
      out[i].reg9_pass1 = arith::wrap(F::reg9, static_cast<code_t>(top_.obs_reg9_q));
      fall();
      in_flight_ = true;
    }
    if (in_flight_) finish(collect, done);
    if (done != count)
      throw std::logic_error("RTL sync twin: pin 35 rose " + std::to_string(done) + " times for " +
                             std::to_string(count) + " operations");
  }

  std::uint64_t half_periods() const override { return edges_; }
  bool fixed() const override { return IsFixed; }

 private:
  /// The operation in flight: pass 2 and 35↑ on the next rising edge.
  template <class Collect>
  void finish(const Collect& collect, std::size_t done) {
    rise();
    expect_done_rose(done);
    collect(done);
    fall();
    in_flight_ = false;
  }

  void expect_done_rose(std::size_t index) const {
    if (!top_.pin35_done || top_.obs_select36)
      throw std::logic_error("RTL sync twin: 35 not high or select 36 still high 2 T after start " +
                             std::to_string(index));
  }

  void rise() {
    top_.pin28_clk = 1;
    top_.eval();
    ++edges_;
  }
  void fall() {
    if constexpr (IsFixed) {
      show_clock_low(top_);  // verilated_clock.h: no eval() where Verilator allows it
    } else {
      top_.pin28_clk = 0;
      top_.eval();
    }
    ++edges_;
  }

  Formats formats_;
  VerilatedContext context_;
  ThreadContextGuard context_guard_{context_};  // between the two: see there
  Top top_;
  RtlCoverageScope coverage_{context_};  // after the model: read before it goes
  std::uint64_t edges_ = 0;
  bool loaded_ = false;
  bool in_flight_ = false;
  code_t loaded_n_ = 0;
  std::array<code_t, 3> loaded_rgb_{};
  std::uint64_t start_edge_[2] = {0, 0};  // at most two operations overlap
};

}  // namespace specular
