// specular_bench: what every measured model shares — the inputs, the checksum, the
// figure lines and the plan of how many operations each model runs.
//
// Every model runs in its own child process (an elaborated pin model's clock keeps
// ticking and would slow anything measured beside it); a child prints its figures as
// `name: value unit` lines, and the parent adds the ratios to std::pow.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/systemc.h"

namespace specular_bench {

using specular::Operands;
using specular::Result;

/// How many operations a child runs, and on what. The parent passes these on the
/// command line, so every child draws the same inputs.
struct Plan {
  std::uint64_t seed = 6;         ///< the issue's number: fixed, so every run sees the same inputs
  std::size_t ops = 0;            ///< operations timed per repetition
  int repetitions = 1;            ///< the best repetition counts (a noisy machine only slows runs)
  std::size_t verify_ops = 0;     ///< the checksum every model prints is over this prefix
  std::string vcd_path;           ///< where the VCD-on pin model writes its trace (+ ".vcd")
  bool keep_vcd = false;          ///< keep the trace for a look in GTKWave
};

/// The random operands every model sees, in the same order: a ring of 2^16 draws
/// (cos λ uniform in [0, 1], n uniform in 1..1000, R, G, B uniform in 0..255), cycled
/// when a model runs more operations than that. Operation i uses ring[i mod 2^16].
constexpr std::size_t ring_size = std::size_t{1} << 16;
std::vector<Operands> random_operands(const specular::Core& core, std::uint64_t seed);

/// The streaming variant: cos λ of operation i, but n, R, G, B held for blocks of
/// `stream_block` operations (a surface of one material), so the pin model may start
/// every 2 T instead of 3 T (spec §3 protocol).
constexpr std::size_t stream_block = 256;
Operands stream_operand(const std::vector<Operands>& ring, std::size_t i);

/// Order-dependent hash of pins 24–26, the part of a result every model exposes.
/// Models agree bit for bit exactly when their checksums agree.
struct Checksum {
  std::uint64_t value = 0xcbf29ce484222325ull;
  void add(const std::array<specular::code_t, 3>& out) {
    for (const specular::code_t code : out) {
      value ^= static_cast<std::uint64_t>(code);
      value *= 0x100000001b3ull;
    }
  }
};

/// One figure line: `name: value unit`, the format the issue asks for.
void print_figure(const std::string& name, double value, const std::string& unit);
void print_checksum(const std::string& name, std::uint64_t value);
/// Peak resident memory of this process (VmHWM of /proc/self/status), in kB.
long peak_memory_kb();
/// Seconds on a monotonic clock.
double now_seconds();

// ---- the models: each measures itself and prints its figures -----------------------
/// `name`: pow, or pow_end (the yardstick measured again after every model).
void measure_pow(const Plan& plan, const std::string& name);
void measure_core(const Plan& plan);
/// A design variant's C++ model (issue 26): figures variant_NAME_rate, _checksum, …
void measure_variant(const Plan& plan, const std::string& variant_name);
/// specular_tb's rows with the core model: core, comparison and the CSV (or JSON) writer.
void measure_rows(const Plan& plan, const std::string& name, bool json);
void measure_rows_nlohmann(const Plan& plan, const std::string& name, bool serializer);
/// What the pin-level device writes to plan.vcd_path while it runs.
enum class Trace {
  off,
  vcd,             ///< every pin and net, as `specular_tb --vcd` traces them
  vcd_real_views,  ///< the same plus the *_real views (`specular_tb --vcd --real-views`)
};
/// Which device DeviceHarness drives in measure_pin.
enum class PinDevice {
  netlist,  ///< the SystemC netlist of Fig. 1–2 (PinHarness)
  rtl,      ///< the RTL twin, verilated (RtlHarness)
  rtl_sync, ///< the synchronous variant, verilated (RtlSyncHarness, its own protocol)
  floor,    ///< FloorDevice: timing only, no arithmetic (the harness and kernel's floor)
};
/// A pin-level device under DeviceHarness. `stream`: n/RGB held per block.
void measure_pin(const Plan& plan, const std::string& name, bool stream, Trace trace,
                 PinDevice device = PinDevice::netlist);
/// The RTL twin as plain C++ (RtlCycleModel), clocked without the kernel.
void measure_rtl_cycle_model(const Plan& plan, const std::string& name, bool stream,
                             bool allow_fixed = true);
/// The synchronous variant as plain C++ (RtlSyncCycleModel): the fast cycle model.
void measure_rtl_sync_cycle_model(const Plan& plan, const std::string& name, bool stream,
                                  bool allow_fixed = true);

/// How a TLM model is driven (SpecularDriver over a simple_initiator_socket).
struct TlmOptions {
  bool pin = false;      ///< SpecularPinTarget (the netlist behind a transactor), else lt
  bool batch = false;    ///< BATCH_COS bursts on the streaming inputs, else compute() per result
  sc_core::sc_time quantum;  ///< global quantum of the tlm_quantumkeeper; zero: no decoupling
  bool burst = false;    ///< compute_burst() per result (OPERANDS / RESULTS), else compute()
  bool rtl = false;      ///< SpecularRtlTarget (the RTL twin clocked in b_transport); overrides pin
  bool energy = true;    ///< the target's energy model (issue 61) on, as it is by default
};
void measure_tlm(const Plan& plan, const std::string& name, const TlmOptions& options);

}  // namespace specular_bench
