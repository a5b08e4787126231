// The TLM-2.0 models (modules/include/specular/tlm/), driven as software would drive
// them: SpecularDriver over a simple_initiator_socket, with a tlm_quantumkeeper.
#include <algorithm>
#include <memory>

#include <tlm_utils/simple_initiator_socket.h>

#include "bench.h"
#include "specular/tlm/driver.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/twin/rtl_target.h"

namespace specular_bench {

namespace {

using sc_core::sc_time;

const sc_time clock_period(10, sc_core::SC_NS);

class TlmBench : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<TlmBench, 32> socket{"socket"};

  TlmBench(sc_core::sc_module_name name, const Plan& plan, const TlmOptions& options)
      : sc_module(name), plan_(plan), options_(options), ring_(random_operands(core_, plan.seed)) {
    SPECULAR_HAS_PROCESS(TlmBench);
    if (options.rtl)
      target_ = std::make_unique<specular::SpecularRtlTarget>("ip", specular::Config{}, clock_period);
    else if (options.pin)
      target_ = std::make_unique<specular::SpecularPinTarget>("ip", specular::Config{}, clock_period);
    else
      target_ = std::make_unique<specular::SpecularLtTarget>("ip", specular::Config{}, clock_period);
    socket.bind(target_->socket);
    target_->done_irq(done_irq_);
    target_->set_energy_model(options.energy);
    for (std::size_t i = 0; i < ring_size; ++i) cos_ring_[i] = static_cast<std::uint32_t>(ring_[i].cos);
    SC_THREAD(drive);
  }

  Checksum verify;
  Checksum work;
  double seconds = 0.0;
  sc_time simulated;

 private:
  void add(std::size_t i, const std::int32_t* out) {
    const std::array<specular::code_t, 3> codes{out[0], out[1], out[2]};
    if (first_pass_ && i < plan_.verify_ops) verify.add(codes);
    work.add(codes);
  }

  void drive() {
    // Without temporal decoupling the quantum is zero: the keeper syncs (waits) after
    // every transaction, as an initiator that never runs ahead would.
    // A platform pulses the device's reset (pin 29) before using it (spec §3).
    if (auto* pin = dynamic_cast<specular::SpecularPinTarget*>(target_.get())) pin->harness.reset();
    tlm_utils::tlm_quantumkeeper::set_global_quantum(options_.quantum);
    tlm_utils::tlm_quantumkeeper keeper;
    keeper.reset();
    specular::SpecularDriver driver(socket, 0, keeper);
    std::vector<std::int32_t> out(3 * stream_block);

    seconds = 1e300;
    for (int rep = 0; rep < plan_.repetitions; ++rep) {
      first_pass_ = rep == 0;
      const sc_time sim0 = sc_core::sc_time_stamp() + keeper.get_local_time();
      const double t0 = now_seconds();
      if (options_.batch) {
        // BATCH_COS / BATCH_OUT: one burst of cos codes per block sharing n, R, G, B.
        for (std::size_t first = 0; first < plan_.ops; first += stream_block) {
          const std::size_t count = std::min(stream_block, plan_.ops - first);
          const Operands& shared = ring_[first % ring_size];
          driver.compute_batch(shared.n, shared.rgb, &cos_ring_[first % ring_size], count,
                               out.data());
          for (std::size_t j = 0; j < count; ++j) add(first + j, &out[3 * j]);
        }
      } else if (options_.burst) {
        // The fast path: OPERANDS (COS, N, R, G, B, START) and RESULTS, two bursts per result.
        for (std::size_t i = 0; i < plan_.ops; ++i)
          add(i, driver.compute_burst(ring_[i % ring_size]).data());
      } else {
        for (std::size_t i = 0; i < plan_.ops; ++i) add(i, driver.compute(ring_[i % ring_size]).data());
      }
      keeper.sync();
      seconds = std::min(seconds, now_seconds() - t0);
      simulated = sc_core::sc_time_stamp() - sim0;
    }
    sc_core::sc_stop();
  }

  bool first_pass_ = true;
  const specular::Core core_;
  const Plan& plan_;
  TlmOptions options_;
  std::vector<Operands> ring_;
  std::array<std::uint32_t, ring_size> cos_ring_{};
  std::unique_ptr<specular::SpecularTarget> target_;
  sc_core::sc_signal<bool> done_irq_{"done_irq"};
};

}  // namespace

void measure_tlm(const Plan& plan, const std::string& name, const TlmOptions& options) {
  TlmBench bench("bench", plan, options);
  sc_core::sc_start();
  const double ops = static_cast<double>(plan.ops);
  print_figure(name + "_rate", ops / bench.seconds / 1e6, "Mresults/s");
  print_figure(name + "_simulated_per_result", bench.simulated / clock_period / ops, "T");
  print_checksum(name + "_checksum", bench.verify.value);
  print_checksum(name + "_work", bench.work.value);
  print_figure(name + "_peak_memory", static_cast<double>(peak_memory_kb()), "kB");
}

}  // namespace specular_bench
