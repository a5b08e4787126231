#include "soak.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "cli.h"
#include "progress.h"
#include "run_models.h"
#include "scoreboard.h"
#include "specular/pin_harness.h"
#include "specular/tlm/driver.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"

namespace specular {
namespace soak {

using tb::Stimulus;

// ---- options -------------------------------------------------------------------------

const char* const soak_description = "Constrained-random soak of the specular device models.";

const char* const soak_footer =
    "Every result is compared with the double reference (tolerances of reference.h); pin and TLM "
    "results must equal the core's bit for bit. Each SystemC stage runs in a child process of its "
    "own. One line per stage: ops, mismatches, time, VmRSS early (after a tenth of the stage) and "
    "late (at its end). Exit status 0 when no stage has a mismatch, 1 otherwise, 2 for a bad option.";

void add_soak_options(specular::cli::Command& app, SoakOptions& o) {
  const auto count = [&](const std::string& name, std::size_t& target, const std::string& help) {
    app.add_option(name, target, help)
        ->type_name("N")
        ->capture_default_str()
        ->check(cli::integer_in(0, 1000000000));
  };
  count("--core", o.core_ops,
        "operations through the bit-accurate core, cycling through every normalisation and "
        "saturation policy");
  count("--pin", o.pin_ops, "operations through the pin-level device, driven on its pins");
  count("--tlm", o.tlm_ops,
        "operations through the TLM lt target over a bus, with temporal decoupling (1 us quantum), "
        "single and batch transactions");
  count("--tlm-pin", o.tlm_pin_ops, "operations through the TLM pin target (transactor)");
  cli::add_parsed(app, "--pin-delay", o.pin_delay, pin_delay_from_string,
                  "the TLM pin target's delay policy (default keep: the delay the initiator "
                  "annotates is returned unchanged; docs/integration.md section 6)")
      ->type_name("keep|consume");
  app.add_option("--seed", o.seed, "seed of the 64-bit Mersenne Twister")
      ->type_name("S")
      ->capture_default_str()
      ->check(cli::unsigned64());
  cli::add_parsed(app, "--constants", o.constants, parse_constants,
                  "the device's pins 19 (h), 20 (a) and ROM 38's scale in every stage, the "
                  "reference's too (default patent); the core stage skips the policies the device "
                  "refuses under them")
      ->type_name("patent|minimax-half|minimax");
  app.add_option("--inject-fault", o.inject_fault,
                 "corrupt operation K of every stage (self-check of the scoreboard; 0: none)")
      ->type_name("K")
      ->check(cli::integer_in(0, 1000000000));
  app.add_flag("--quiet", o.quiet,
               "no progress line (drawn on standard error only when it is a terminal: operations "
               "done, total, rate, time left)");
}

// ---- stimuli -------------------------------------------------------------------------

Stimuli::Stimuli(const Formats& formats, std::uint64_t seed) : formats_(formats), engine_(seed) {}

std::uint64_t Stimuli::below(std::uint64_t span) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                              std::numeric_limits<std::uint64_t>::max() % span;
  std::uint64_t value;
  do value = engine_(); while (value >= limit);
  return value % span;
}

code_t Stimuli::cos_code(unsigned n) {
  const code_t one = formats_.cos.one();
  switch (below(8)) {
    case 0: return below(2) ? one : 0;                                     // the ends
    case 1: return one - 1 - static_cast<code_t>(below(4096));             // just below 1
    case 2: return static_cast<code_t>(below(64));                         // tiny, log2 0
    case 3: {  // around A = 0 (x = −3): cos = 2^(−3/n), ± 64 codes
      const code_t centre = static_cast<code_t>(std::llround(std::exp2(-3.0 / n) * one));
      const code_t code = centre - 64 + static_cast<code_t>(below(129));
      return code < 0 ? 0 : (code > one ? one : code);
    }
    default: return static_cast<code_t>(below(static_cast<std::uint64_t>(one) + 1));  // uniform
  }
}

void Stimuli::next(std::vector<Stimulus>& chunk, std::size_t count) {
  chunk.resize(count);
  const auto rgb_span = static_cast<std::uint64_t>(formats_.rgb.max_code()) + 1;
  for (Stimulus& s : chunk) {
    if (run_left_ == 0) {  // a new run of operations sharing n and R, G, B
      run_left_ = below(4) == 0 ? 1 : 1 + static_cast<unsigned>(below(32));
      switch (below(8)) {
        case 0: n_ = n_min; break;
        case 1: n_ = n_max; break;
        default: n_ = n_min + static_cast<unsigned>(below(n_max - n_min + 1)); break;
      }
      for (unsigned& c : rgb_) {
        const auto pick = below(8);
        c = pick == 0 ? 0u : pick == 1 ? static_cast<unsigned>(rgb_span - 1)
                                       : static_cast<unsigned>(below(rgb_span));
      }
    }
    --run_left_;
    s.n = n_;
    s.rgb = rgb_;
    s.operands.n = n_;
    for (int ch = 0; ch < 3; ++ch) s.operands.rgb[ch] = rgb_[ch];
    s.operands.cos = cos_code(n_);
    s.cos = formats_.cos.to_real(s.operands.cos);
  }
}

// ---- measurement ---------------------------------------------------------------------

long resident_kib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

std::string format_figures(const StageFigures& f) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(2);
  s << "soak " << f.stage << ": ops=" << f.ops << " mismatches=" << f.mismatches
    << " reference_failures=" << f.reference_failures << " bit_mismatches=" << f.bit_mismatches
    << " seconds=" << f.seconds << " rss_early_kib=" << f.rss_early_kib
    << " rss_late_kib=" << f.rss_late_kib;
  if (f.config_register >= 0) s << " config=" << f.config_register;
  return s.str();
}

namespace {

constexpr std::size_t chunk_size = 4096;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool same_bits(const Result& a, const Result& b) {
  return a.reg1 == b.reg1 && a.reg9_pass1 == b.reg9_pass1 && a.reg9_pass2 == b.reg9_pass2 &&
         a.rom38_k == b.rom38_k && a.norm39 == b.norm39 && a.out == b.out;
}

/// Counts failures for one stage, samples VmRSS early and late, and draws specular_tb's
/// progress line (progress.h) while the stage runs: only on a terminal, not with --quiet.
class Tally {
 public:
  Tally(std::string stage, std::size_t planned, std::size_t inject_fault, bool quiet)
      : planned_(planned), inject_fault_(inject_fault), start_(std::chrono::steady_clock::now()),
        progress_(std::cerr, planned, tb::progress_wanted(quiet), "operations", stage) {
    figures_.stage = std::move(stage);
  }

  /// One operation: `model` from the model under test, `expected` from the core (or
  /// nullptr for the core stage itself).
  void check(tb::Scoreboard& scoreboard, const Stimulus& s, Result model, const Result* expected,
             double cycles) {
    ++figures_.ops;
    if (figures_.ops == inject_fault_) model.out[0] ^= code_t{1} << 23;  // 1024 units of R
    const tb::Comparison c = scoreboard.compare(s, model, cycles);
    scoreboard.record(c);
    const bool reference_ok = c.pass();
    const bool bits_ok = expected == nullptr || same_bits(model, *expected);
    if (!reference_ok) ++figures_.reference_failures;
    if (!bits_ok) ++figures_.bit_mismatches;
    if (!reference_ok || !bits_ok) ++figures_.mismatches;
    if (figures_.rss_early_kib == 0 && figures_.ops >= planned_ / 10) figures_.rss_early_kib = resident_kib();
    if (figures_.ops % 1024 == 0) progress_.update(figures_.ops);  // a clock read per 1024
  }

  StageFigures finish() {
    progress_.finish();
    figures_.seconds = seconds_since(start_);
    figures_.rss_late_kib = resident_kib();
    if (figures_.rss_early_kib == 0) figures_.rss_early_kib = figures_.rss_late_kib;
    return figures_;
  }

 private:
  std::size_t planned_;
  std::size_t inject_fault_;
  std::chrono::steady_clock::time_point start_;
  tb::Progress progress_;
  StageFigures figures_;
};

}  // namespace

// ---- core ----------------------------------------------------------------------------

Config soak_config(const SoakOptions& options) {
  Config config;
  config.constants = options.constants;
  return config;
}

StageFigures run_core_stage(const SoakOptions& options, std::vector<std::string>* skipped) {
  struct Policy {
    std::unique_ptr<Core> core;
    std::unique_ptr<tb::Scoreboard> scoreboard;
  };
  std::vector<Policy> policies;
  for (const Normalisation normalisation :
       {Normalisation::patent, Normalisation::energy, Normalisation::none})
    for (const Saturation saturation : {Saturation::clamp, Saturation::literal}) {
      Config config = soak_config(options);
      config.normalisation = normalisation;
      config.saturation = saturation;
      try {
        policies.push_back({std::make_unique<Core>(config), std::make_unique<tb::Scoreboard>(config)});
      } catch (const std::invalid_argument&) {  // a device that cannot be built (arith.cpp)
        if (skipped)
          skipped->push_back(std::string(to_string(normalisation)) + "/" + to_string(saturation));
      }
    }
  Stimuli stimuli(Formats(soak_config(options).widths), options.seed);
  Tally tally("core", options.core_ops, options.inject_fault, options.quiet);
  std::vector<Stimulus> chunk;
  std::size_t policy = 0;
  for (std::size_t done = 0; done < options.core_ops; done += chunk.size()) {
    stimuli.next(chunk, std::min(chunk_size, options.core_ops - done));
    Policy& p = policies[policy];
    policy = (policy + 1) % policies.size();
    for (const Stimulus& s : chunk)
      tally.check(*p.scoreboard, s, p.core->run(s.operands), nullptr, tb::spec_latency_cycles);
  }
  return tally.finish();
}

// ---- pin-level device -----------------------------------------------------------------

namespace {

class PinSoak : public sc_core::sc_module {
 public:
  PinSoak(sc_core::sc_module_name name, const SoakOptions& options)
      : sc_module(name),
        harness("harness", soak_config(options), sc_core::sc_time(10, sc_core::SC_NS)),
        options_(options),
        tally_("pin", options.pin_ops, options.inject_fault, options.quiet),
        scoreboard_(soak_config(options)),
        core_(soak_config(options)) {
    SPECULAR_HAS_PROCESS(PinSoak);
    SC_THREAD(run);
  }

  PinHarness harness;
  StageFigures figures;

 private:
  void run() {
    harness.reset();
    Stimuli stimuli(core_.formats(), options_.seed + 1);
    std::vector<Stimulus> chunk;
    std::vector<Operands> in;
    std::vector<Result> out;
    for (std::size_t done = 0; done < options_.pin_ops; done += chunk.size()) {
      stimuli.next(chunk, std::min(chunk_size, options_.pin_ops - done));
      in.resize(chunk.size());
      for (std::size_t i = 0; i < chunk.size(); ++i) in[i] = chunk[i].operands;
      harness.run_batch(in, out);
      for (std::size_t i = 0; i < chunk.size(); ++i) {
        const Result expected = core_.run(in[i]);
        tally_.check(scoreboard_, chunk[i], out[i], &expected, harness.cycles()[i]);
      }
    }
    figures = tally_.finish();
    sc_core::sc_stop();
  }

  SoakOptions options_;
  Tally tally_;
  tb::Scoreboard scoreboard_;
  Core core_;
};

}  // namespace

StageFigures run_pin_stage(const SoakOptions& options) {
  auto* soak = new PinSoak("soak", options);  // SystemC objects live until exit
  sc_core::sc_start();
  return soak->figures;
}

// ---- TLM -------------------------------------------------------------------------------

namespace {

class TlmSoak : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<TlmSoak, 32> socket{"socket"};

  TlmSoak(sc_core::sc_module_name name, const SoakOptions& options, bool pin_target)
      : sc_module(name),
        options_(options),
        pin_target_(pin_target),
        count_(pin_target ? options.tlm_pin_ops : options.tlm_ops),
        tally_(pin_target ? "tlm-pin" : "tlm", count_, options.inject_fault, options.quiet),
        scoreboard_(soak_config(options)),
        core_(soak_config(options)) {
    SPECULAR_HAS_PROCESS(TlmSoak);
    const sc_core::sc_time period(10, sc_core::SC_NS);
    if (pin_target) {
      PinTargetSettings settings;
      settings.clock_period = period;
      settings.delay = options.pin_delay;
      target_ = std::make_unique<SpecularPinTarget>("target", soak_config(options), settings);
    }
    else {
      target_ = std::make_unique<SpecularLtTarget>("target", soak_config(options), period);
    }
    socket.bind(target_->socket);
    target_->done_irq(irq_);
    SC_THREAD(run);
  }

  StageFigures figures;

 private:
  void run() {
    if (auto* pin = dynamic_cast<SpecularPinTarget*>(target_.get())) pin->harness.reset();
    tlm_utils::tlm_quantumkeeper::set_global_quantum(sc_core::sc_time(1, sc_core::SC_US));
    tlm_utils::tlm_quantumkeeper keeper;
    keeper.reset();
    SpecularDriver driver(socket, 0, keeper);
    Stimuli stimuli(core_.formats(), options_.seed + 2);
    std::vector<Stimulus> chunk;
    std::vector<std::uint32_t> cos;
    std::vector<std::int32_t> out;
    bool batch = false;
    for (std::size_t done = 0; done < count_; done += chunk.size(), batch = !batch) {
      stimuli.next(chunk, std::min<std::size_t>(batch ? 512 : chunk_size, count_ - done));
      if (!batch) {  // register by register, every inspection register read back
        for (const Stimulus& s : chunk) {
          const Result got = driver.compute_inspected(s.operands);
          const Result expected = core_.run(s.operands);
          // lt annotates start → 35↑ exactly; the transactor's duration also holds the
          // wait for the next clock edge (its timing is tested in test_tlm_timing).
          const double cycles = pin_target_ ? tb::spec_latency_cycles
                                            : driver.operation_duration() / target_->clock_period();
          tally_.check(scoreboard_, s, got, &expected, cycles);
        }
        continue;
      }
      // BATCH_COS / BATCH_OUT: the chunk shares its first operation's n and R, G, B.
      cos.resize(chunk.size());
      out.resize(3 * chunk.size());
      for (std::size_t i = 0; i < chunk.size(); ++i) {
        chunk[i].n = chunk[0].n;
        chunk[i].rgb = chunk[0].rgb;
        chunk[i].operands.n = chunk[0].operands.n;
        chunk[i].operands.rgb = chunk[0].operands.rgb;
        cos[i] = static_cast<std::uint32_t>(chunk[i].operands.cos);
      }
      driver.compute_batch(chunk[0].operands.n, chunk[0].operands.rgb, cos.data(), chunk.size(),
                           out.data());
      for (std::size_t i = 0; i < chunk.size(); ++i) {
        const Result expected = core_.run(chunk[i].operands);
        Result got = expected;  // a batch returns pins 24–26 only
        for (int ch = 0; ch < 3; ++ch) got.out[ch] = out[3 * i + ch];
        tally_.check(scoreboard_, chunk[i], got, &expected, tb::spec_latency_cycles);
      }
    }
    keeper.sync();
    figures = tally_.finish();
    figures.config_register = driver.read(Reg::config);
    sc_core::sc_stop();
  }

  SoakOptions options_;
  bool pin_target_;
  std::size_t count_;
  Tally tally_;
  tb::Scoreboard scoreboard_;
  Core core_;
  std::unique_ptr<SpecularTarget> target_;
  sc_core::sc_signal<bool> irq_{"irq"};
};

}  // namespace

StageFigures run_tlm_stage(const SoakOptions& options, bool pin_target) {
  auto* soak = new TlmSoak("soak", options, pin_target);  // SystemC objects live until exit
  sc_core::sc_start();
  return soak->figures;
}

}  // namespace soak
}  // namespace specular
