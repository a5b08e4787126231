// The pin-level device of Fig. 1 (PinHarness): the clock, the pins, every block's
// SC_MODULE, driven with the protocol of spec §3; optionally traced to a VCD file.
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <type_traits>

#include "bench.h"
#include "floor_device.h"
#include "specular/pin_harness.h"
#include "specular/twin/rtl_device.h"
#include "specular/twin/rtl_sync_device.h"

namespace specular_bench {

namespace {

using sc_core::sc_time;

/// Clock period of pin 28. Only simulated time depends on it; the wall-clock cost per
/// result depends on the number of clock edges per result (2 T streaming, 3 T otherwise).
const sc_time clock_period(10, sc_core::SC_NS);

/// Operations per run_batch call: enough that the gap between batches (one start slot)
/// is lost in the noise, few enough that the result vectors stay in cache.
constexpr std::size_t chunk = 4096;

template <class Harness>
class PinBench : public sc_core::sc_module {
 public:
  PinBench(sc_core::sc_module_name name, const Plan& plan, bool stream, bool real_views)
      : sc_module(name),
        harness("specular", specular::Config{}, clock_period, real_views),
        plan_(plan),
        stream_(stream),
        ring_(random_operands(core_, plan.seed)) {
    SPECULAR_HAS_PROCESS(PinBench);
    SC_THREAD(drive);
  }

  Harness harness;
  Checksum verify;
  Checksum work;
  double seconds = 0.0;
  double clock_cycles = 0.0;

 private:
  void drive() {
    harness.reset();
    std::vector<Operands> batch;
    std::vector<Result> out;
    const sc_time sim0 = sc_core::sc_time_stamp();
    const double t0 = now_seconds();
    for (std::size_t first = 0; first < plan_.ops; first += chunk) {
      const std::size_t count = std::min(chunk, plan_.ops - first);
      batch.resize(count);
      for (std::size_t j = 0; j < count; ++j)
        batch[j] = stream_ ? stream_operand(ring_, first + j) : ring_[(first + j) % ring_size];
      harness.run_batch(batch, out);
      for (std::size_t j = 0; j < count; ++j) {
        if (first + j < plan_.verify_ops) verify.add(out[j].out);
        work.add(out[j].out);
      }
    }
    seconds = now_seconds() - t0;
    clock_cycles = (sc_core::sc_time_stamp() - sim0) / clock_period;
    sc_core::sc_stop();
  }

  const specular::Core core_;
  const Plan& plan_;
  bool stream_;
  std::vector<Operands> ring_;
};

template <class Harness>
void measure_with(const Plan& plan, const std::string& name, bool stream, Trace trace) {
  const bool vcd = trace != Trace::off;
  PinBench<Harness> bench("bench", plan, stream, trace == Trace::vcd_real_views);
  sc_core::sc_trace_file* file = nullptr;
  if constexpr (std::is_same_v<Harness, specular::RtlHarness> ||
                std::is_same_v<Harness, specular::RtlSyncHarness>) {
    if (vcd) bench.harness.dut.open_vcd(plan.vcd_path + ".vcd");  // Verilator's writer
  } else if (vcd) {
    file = sc_core::sc_create_vcd_trace_file(plan.vcd_path.c_str());  // appends ".vcd"
    bench.harness.trace(file);
  }
  sc_core::sc_start();
  if (file != nullptr) sc_core::sc_close_vcd_trace_file(file);

  const double ops = static_cast<double>(plan.ops);
  print_figure(name + "_rate", ops / bench.seconds / 1e6, "Mresults/s");
  print_figure(name + "_clock_rate", bench.clock_cycles / bench.seconds / 1e6, "Mcycles/s");
  print_figure(name + "_cycles_per_result", bench.clock_cycles / ops, "T");
  if (vcd) {
    const std::string path = plan.vcd_path + ".vcd";
    struct stat info {};
    const double bytes = ::stat(path.c_str(), &info) == 0 ? static_cast<double>(info.st_size) : -1.0;
    print_figure(name + "_bytes_per_result", bytes / ops, "B");
    if (!plan.keep_vcd) std::remove(path.c_str());
  }
  print_checksum(name + "_checksum", bench.verify.value);
  print_checksum(name + "_work", bench.work.value);
  print_figure(name + "_peak_memory", static_cast<double>(peak_memory_kb()), "kB");
}

}  // namespace

void measure_pin(const Plan& plan, const std::string& name, bool stream, Trace trace,
                 PinDevice device) {
  switch (device) {
    case PinDevice::netlist: return measure_with<specular::PinHarness>(plan, name, stream, trace);
    case PinDevice::rtl: return measure_with<specular::RtlHarness>(plan, name, stream, trace);
    case PinDevice::rtl_sync:
      return measure_with<specular::RtlSyncHarness>(plan, name, stream, trace);
    case PinDevice::floor:
      return measure_with<specular::DeviceHarness<FloorDevice>>(plan, name, stream, trace);
  }
}

}  // namespace specular_bench
