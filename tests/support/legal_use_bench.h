// A bench for "any legal TLM-2.0 use" (test_tlm_legal_use.cpp, fuzz_tlm_sequences.cpp):
// one target (lt, pin, rtl or axi) behind BaseProtocolChecker, driven by LegalInitiator
// from any number of threads. The bench runs a setup function, then the worker
// threads side by side, and stops the kernel when the last one ends. No gtest here.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/twin/axi_target.h"
#include "specular/twin/rtl_target.h"
#include "base_protocol_checker.h"
#include "legal_initiator.h"

namespace specular {
namespace tlm_testing {

enum class Target { lt, pin, rtl, axi };

inline const char* to_string(Target target) {
  return target == Target::lt ? "lt" : target == Target::pin ? "pin" : target == Target::rtl ? "rtl" : "axi";
}

inline std::unique_ptr<SpecularTarget> make_target(Target target, const Config& config,
                                                   const sc_core::sc_time& period) {
  if (target == Target::lt) return std::make_unique<SpecularLtTarget>("target", config, period);
  if (target == Target::pin) return std::make_unique<SpecularPinTarget>("target", config, period);
  if (target == Target::rtl) return std::make_unique<SpecularRtlTarget>("target", config, period);
  return std::make_unique<SpecularAxiTarget>("target", config, period);
}

class LegalUseBench : public sc_core::sc_module {
 public:
  using Body = std::function<void(LegalUseBench&, int worker)>;

  LegalUseBench(sc_core::sc_module_name name, Target kind, const Config& config,
                const sc_core::sc_time& period)
      : sc_module(name), kind(kind), period(period), core(config),
        target(make_target(kind, config, period)) {
    cpu.socket.bind(checker.target_socket);
    checker.initiator_socket.bind(target->socket);
    target->done_irq(irq);
  }

  /// Runs `setup`, then `workers` threads of `body` side by side, from time 0 (call
  /// before sc_start; once).
  void start(std::function<void(LegalUseBench&)> setup, int workers, Body body) {
    setup_ = std::move(setup);
    body_ = std::move(body);
    workers_ = workers;
    sc_core::sc_spawn([this] { main(); }, "main");
  }

  const Target kind;
  const sc_core::sc_time period;
  const Core core;  ///< the independent computation every result is compared with
  LegalInitiator cpu{"cpu"};
  BaseProtocolChecker checker{"checker"};
  std::unique_ptr<SpecularTarget> target;
  sc_core::sc_signal<bool> irq{"irq"};

  bool stop_when_done = true;         ///< sc_stop() after the last worker (pin's clock may run)
  std::vector<std::string> failures;  ///< what went wrong, for the test to report
  long compared = 0;                  ///< result words compared with Core
  long accesses = 0;

  void fail(const std::string& what) { failures.push_back(what); }

  /// One access that must be answered TLM_OK_RESPONSE.
  void ok(Path path, tlm::tlm_command command, std::uint64_t address, void* data,
          unsigned length, const sc_core::sc_time& delay = sc_core::SC_ZERO_TIME) {
    ++accesses;
    const tlm::tlm_response_status status = cpu.transport(path, command, address, data, length, delay);
    if (status != tlm::TLM_OK_RESPONSE) {
      tlm::tlm_generic_payload named;
      named.set_response_status(status);
      fail(std::string(to_string(path)) + " at 0x" + hex(address) + " answered " +
           named.get_response_string());
    }
  }

  /// N, R, G, B through OPERANDS words 1–4 (one burst).
  void set_shared(Path path, code_t n, const std::array<code_t, 3>& rgb) {
    std::uint32_t words[4] = {static_cast<std::uint32_t>(n), static_cast<std::uint32_t>(rgb[0]),
                              static_cast<std::uint32_t>(rgb[1]), static_cast<std::uint32_t>(rgb[2])};
    ok(path, tlm::TLM_WRITE_COMMAND, offset_of(Reg::operands) + 4, words, sizeof words);
  }

  /// One operation: the OPERANDS burst with START (write path), then the RESULTS burst
  /// (read path); checks the three outputs against Core unless `exact` is false (only
  /// exact when no other thread starts operations in between). Returns what was read.
  std::array<std::int32_t, 3> single(Path write, Path read, const Operands& op,
                                     const sc_core::sc_time& delay = sc_core::SC_ZERO_TIME,
                                     bool exact = true) {
    std::uint32_t words[6] = {static_cast<std::uint32_t>(op.cos), static_cast<std::uint32_t>(op.n),
                              static_cast<std::uint32_t>(op.rgb[0]),
                              static_cast<std::uint32_t>(op.rgb[1]),
                              static_cast<std::uint32_t>(op.rgb[2]), control_bits::start};
    ok(write, tlm::TLM_WRITE_COMMAND, offset_of(Reg::operands), words, sizeof words, delay);
    std::int32_t out[3] = {0, 0, 0};
    ok(read, tlm::TLM_READ_COMMAND, offset_of(Reg::results), out, sizeof out);
    if (exact) check(op, out, "single operation");
    return {out[0], out[1], out[2]};
  }

  /// k operations through the batch window at word `first` (N, R, G, B as last set):
  /// BATCH_COS burst, then the BATCH_OUT burst; checks every output against Core.
  void batch(Path write, Path read, std::uint32_t first, const std::vector<std::uint32_t>& cos,
             code_t n, const std::array<code_t, 3>& rgb,
             const sc_core::sc_time& delay = sc_core::SC_ZERO_TIME) {
    std::vector<std::uint32_t> in = cos;
    ok(write, tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos) + 4 * first, in.data(),
       static_cast<unsigned>(4 * in.size()), delay);
    std::vector<std::int32_t> out(3 * cos.size(), 0);
    ok(read, tlm::TLM_READ_COMMAND, offset_of(Reg::batch_out) + 12 * first, out.data(),
       static_cast<unsigned>(4 * out.size()));
    for (std::size_t i = 0; i < cos.size(); ++i) {
      Operands op;
      op.cos = cos[i];
      op.n = n;
      op.rgb = rgb;
      check(op, &out[3 * i], "batch word " + std::to_string(first + i));
    }
  }

  static std::string hex(std::uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "%llx", static_cast<unsigned long long>(value));
    return text;
  }

 private:
  void check(const Operands& op, const std::int32_t* out, const std::string& what) {
    const Result expected = core.run(op);
    for (int ch = 0; ch < 3; ++ch) {
      ++compared;
      if (out[ch] != static_cast<std::int32_t>(expected.out[ch]))
        fail(what + ": cos " + std::to_string(op.cos) + " n " + std::to_string(op.n) +
             " channel " + std::to_string(ch) + " read " + std::to_string(out[ch]) +
             ", Core " + std::to_string(expected.out[ch]));
    }
  }

  void main() {
    if (setup_) setup_(*this);
    for (int w = 0; w < workers_; ++w)
      sc_core::sc_spawn(
          [this, w] {
            body_(*this, w);
            if (++finished_ == workers_ && stop_when_done) sc_core::sc_stop();
          },
          ("worker" + std::to_string(w)).c_str());
    if (workers_ == 0 && stop_when_done) sc_core::sc_stop();
  }

  std::function<void(LegalUseBench&)> setup_;
  Body body_;
  int workers_ = 0;
  int finished_ = 0;
};

}  // namespace tlm_testing
}  // namespace specular
