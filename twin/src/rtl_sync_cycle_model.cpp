#include "specular/twin/rtl_sync_cycle_model.h"

#include <array>
#include <stdexcept>
#include <string>

#include <verilated.h>

#include "Vspecular_device_sync_fast.h"
#include "Vspecular_device_sync_fast___024root.h"
#include "specular/arith.h"
#include "specular/rom38_banks.h"
#include "rom_loader.h"
#include "same_formats.h"

namespace specular {

namespace {

std::uint64_t low_bits(code_t code, int width) {
  return static_cast<std::uint64_t>(code) & ((std::uint64_t{1} << width) - 1);
}

}  // namespace

/// The verilated synchronous device and its protocol. Inputs are levels sampled at
/// the rising edge: they are written between edges without an evaluation of their
/// own (nothing in the device reacts to them before the edge), so a clock period costs
/// two evaluations, the rising edge and the falling one Verilator needs to see the
/// next rising edge.
class RtlSyncCycleModel::Engine {
 public:
  explicit Engine(const Config& config) : formats_(config.widths), top_(&context_) {
    load_rom_words(*top_.rootp, formats_);
    top_.cfg_literal = config.saturation == Saturation::literal;
    top_.cfg_rom38_bank = rom38_bank(config);
    top_.pin19_h = static_cast<std::uint32_t>(low_bits(pin19_code(config), formats_.mux4.width()));
    top_.pin20_a = low_bits(pin20_code(config), formats_.reg9.width());
    top_.pin34_carry = 1;
    top_.pin29_reset_n = 1;
    top_.pin28_clk = 0;
    top_.pin27_start = 0;
    top_.pin30_load_n = top_.pin31_load_r = top_.pin32_load_g = top_.pin33_load_b = 0;
    top_.eval();
  }
  ~Engine() { top_.final(); }

  void reset() {
    top_.pin29_reset_n = 0;
    rise();
    fall();
    top_.pin29_reset_n = 1;
    loaded_ = false;
    in_flight_ = false;
  }

  /// `cycles` may be null (the bench's loop).
  void run_batch(const Operands* in, Result* out, double* cycles, std::size_t count) {
    std::size_t done = 0;
    const auto collect = [&](std::size_t index) {
      Result& r = out[index];
      r.reg9_pass2 = arith::wrap(formats_.reg9, static_cast<code_t>(top_.obs_reg9_q));
      r.rom38_k = static_cast<code_t>(top_.obs_rom38_k);
      r.norm39 = arith::wrap(formats_.norm, static_cast<code_t>(top_.obs_mul39_norm));
      r.out = {arith::wrap(formats_.out, static_cast<code_t>(top_.pin24_r)),
               arith::wrap(formats_.out, static_cast<code_t>(top_.pin25_g)),
               arith::wrap(formats_.out, static_cast<code_t>(top_.pin26_b))};
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
      top_.pin17_cos = static_cast<std::uint32_t>(low_bits(op.cos, formats_.cos.width()));
      if (reload) {
        top_.pin18_n = static_cast<std::uint16_t>(low_bits(op.n, formats_.n.width()));
        top_.pin21_r = static_cast<std::uint8_t>(low_bits(op.rgb[0], formats_.rgb.width()));
        top_.pin22_g = static_cast<std::uint8_t>(low_bits(op.rgb[1], formats_.rgb.width()));
        top_.pin23_b = static_cast<std::uint8_t>(low_bits(op.rgb[2], formats_.rgb.width()));
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
      out[i].reg9_pass1 = arith::wrap(formats_.reg9, static_cast<code_t>(top_.obs_reg9_q));
      fall();
      in_flight_ = true;
    }
    if (in_flight_) finish(collect, done);
    if (done != count)
      throw std::logic_error("RTL sync twin: pin 35 rose " + std::to_string(done) + " times for " +
                             std::to_string(count) + " operations");
  }

  std::uint64_t half_periods() const { return edges_; }

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
    top_.pin28_clk = 0;
    top_.eval();
    ++edges_;
  }

  Formats formats_;
  VerilatedContext context_;
  Vspecular_device_sync_fast top_;
  std::uint64_t edges_ = 0;
  bool loaded_ = false;
  bool in_flight_ = false;
  code_t loaded_n_ = 0;
  std::array<code_t, 3> loaded_rgb_{};
  std::uint64_t start_edge_[2] = {0, 0};  // at most two operations overlap
};

RtlSyncCycleModel::RtlSyncCycleModel(const Config& config) : config_(config) {
  const Formats formats(config.widths);
  arith::Rom38Table check(formats, config);  // a device the core refuses, the twin refuses too
  if (!same_formats(config.widths, Widths{}))
    throw std::invalid_argument(
        "the synchronous RTL twin is verilated at the default widths of docs/design.md only");
  engine_ = std::make_unique<Engine>(config);
}

RtlSyncCycleModel::~RtlSyncCycleModel() = default;

void RtlSyncCycleModel::reset() { engine_->reset(); }

Result RtlSyncCycleModel::run(const Operands& in) {
  std::vector<Result> out;
  run_batch({in}, out);
  return out.front();
}

void RtlSyncCycleModel::run_batch(const std::vector<Operands>& in, std::vector<Result>& out) {
  out.assign(in.size(), Result{});
  cycles_.assign(in.size(), 0.0);
  engine_->run_batch(in.data(), out.data(), cycles_.data(), in.size());
}

void RtlSyncCycleModel::run_batch(const Operands* in, Result* out, std::size_t count) {
  engine_->run_batch(in, out, nullptr, count);
}

std::uint64_t RtlSyncCycleModel::half_periods() const { return engine_->half_periods(); }

}  // namespace specular
