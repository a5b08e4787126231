// A bench for the TLM tests (test_tlm_*): one or more targets (lt, pin, rtl, rtl_sync, axi), each behind
// its own initiator socket with a SpecularDriver, its done_irq recorded edge by edge,
// and scenario threads that run the test body. One elaboration per TEST.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "functional_coverage.h"
#include "specular/tlm/driver.h"
#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/twin/axi_target.h"
#include "specular/twin/rtl_sync_target.h"
#include "specular/twin/rtl_target.h"

namespace specular {
namespace tlm_testing {

using sc_core::sc_time;
using sc_core::SC_NS;

enum class Kind { lt, pin, rtl, rtl_sync, axi };

inline const char* to_string(Kind kind) {
  switch (kind) {
    case Kind::lt: return "lt";
    case Kind::pin: return "pin";
    case Kind::rtl: return "rtl";
    case Kind::rtl_sync: return "rtl_sync";
    case Kind::axi: return "axi";
  }
  return "unknown";
}

/// One target with the initiator side that talks to it.
class Endpoint : public sc_core::sc_module {
 public:
  /// bind_irq false: done_irq is left unbound, as on a platform whose interrupt controller
  /// does not take (masks) the line and whose software polls STATUS.done; the target then
  /// drives a signal of its own, and irq_edges come from on_done_irq().
  Endpoint(sc_core::sc_module_name name, Kind kind, const Config& config, const sc_time& period,
           bool bind_irq = true)
      : sc_module(name), kind(kind), driver(socket, 0, keeper), irq_bound_(bind_irq) {
    SPECULAR_HAS_PROCESS(Endpoint);
    testing_support::coverage::record_policy(config);  // functional coverage (issue 37)
    if (kind == Kind::lt)
      target = std::make_unique<SpecularLtTarget>("target", config, period);
    else if (kind == Kind::pin)
      target = std::make_unique<SpecularPinTarget>("target", config, period);
    else if (kind == Kind::rtl)
      target = std::make_unique<SpecularRtlTarget>("target", config, period);
    else if (kind == Kind::rtl_sync)
      target = std::make_unique<SpecularRtlSyncTarget>("target", config, period);
    else
      target = std::make_unique<SpecularAxiTarget>("target", config, period);
    socket.bind(target->socket);
    if (bind_irq) {
      target->done_irq(irq);
      SC_METHOD(on_irq);
      sensitive << irq;
      dont_initialize();
    } else {
      target->on_done_irq([this](bool level) { irq_edges.emplace_back(sc_core::sc_time_stamp(), level); });
    }
  }

  Kind kind;
  tlm_utils::simple_initiator_socket<Endpoint, 32> socket{"socket"};
  sc_core::sc_signal<bool> irq{"irq"};
  std::unique_ptr<SpecularTarget> target;
  tlm_utils::tlm_quantumkeeper keeper;
  SpecularDriver driver;
  std::vector<std::pair<sc_time, bool>> irq_edges;  ///< every change of done_irq

  SpecularPinTarget& pin() { return static_cast<SpecularPinTarget&>(*target); }

  /// One raw b_transport with every payload field under the test's control; the
  /// caller's thread then waits out the annotated delay (no decoupling).
  tlm::tlm_response_status transport(tlm::tlm_command command, std::uint64_t address,
                                     void* data, unsigned length, unsigned streaming_width = 0,
                                     unsigned char* enables = nullptr, unsigned enables_length = 0,
                                     sc_time* annotated = nullptr) {
    tlm::tlm_generic_payload tx;
    tx.set_command(command);
    tx.set_address(address);
    tx.set_data_ptr(static_cast<unsigned char*>(data));
    tx.set_data_length(length);
    tx.set_streaming_width(streaming_width == 0 ? length : streaming_width);
    tx.set_byte_enable_ptr(enables);
    tx.set_byte_enable_length(enables_length);
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = sc_core::SC_ZERO_TIME;
    const bool done_before = target->done_irq_level();  // STATUS.done as the access meets it
    socket->b_transport(tx, delay);
    cover(tx, testing_support::coverage::Transport::b, done_before);
    if (annotated != nullptr) *annotated = delay;
    wait(delay);
    return tx.get_response_status();
  }
  tlm::tlm_response_status write(Reg reg, std::uint32_t value, sc_time* annotated = nullptr) {
    return transport(tlm::TLM_WRITE_COMMAND, offset_of(reg), &value, 4, 0, nullptr, 0, annotated);
  }
  /// A read that must succeed.
  std::uint32_t read(Reg reg) {
    std::uint32_t value = 0xDEADBEEF;
    EXPECT_EQ(transport(tlm::TLM_READ_COMMAND, offset_of(reg), &value, 4), tlm::TLM_OK_RESPONSE)
        << info(reg).name;
    return value;
  }
  std::uint32_t cause() {
    return (read(Reg::status) & status_bits::cause_mask) >> status_bits::cause_shift;
  }
  unsigned debug(tlm::tlm_command command, std::uint64_t address, void* data, unsigned length) {
    tlm::tlm_generic_payload tx;
    tx.set_command(command);
    tx.set_address(address);
    tx.set_data_ptr(static_cast<unsigned char*>(data));
    tx.set_data_length(length);
    const unsigned done = socket->transport_dbg(tx);
    if (testing_support::coverage::enabled() && command != tlm::TLM_IGNORE_COMMAND)
      testing_support::coverage::record_access(address, command == tlm::TLM_WRITE_COMMAND, length,
                                               done == length && length > 0,
                                               testing_support::coverage::Transport::dbg,
                                               static_cast<unsigned char*>(data));
    return done;
  }

 private:
  void on_irq() { irq_edges.emplace_back(sc_core::sc_time_stamp(), irq.read()); }
  // Functional coverage (issue 37): the access, and the done interrupt's order, from the
  // level done_irq had when the access arrived (high: an operation's done not yet
  // acknowledged): a write of 1 to STATUS.done then acknowledges it before the next
  // START; a START (CONTROL, OPERANDS word 5, or a BATCH_COS write) meets it still
  // raised: acknowledged after. Enabled: done_irq bound to the bench's line; masked:
  // left unbound (see the constructor).
  void cover(const tlm::tlm_generic_payload& tx, testing_support::coverage::Transport transport,
             bool done_before) {
    namespace cov = testing_support::coverage;
    if (!cov::enabled() || tx.is_read() == tx.is_write()) return;
    const bool legal = tx.get_response_status() == tlm::TLM_OK_RESPONSE;
    cov::record_access(tx.get_address(), tx.is_write(), tx.get_data_length(), legal, transport,
                       tx.get_data_ptr());
    if (!legal || !tx.is_write() || !done_before) return;
    const std::uint64_t first = tx.get_address();
    const std::uint64_t end = first + tx.get_data_length();
    // the 32-bit word at `offset` if the write covers it whole, else 0
    auto word_at = [&](std::uint64_t offset) -> std::uint32_t {
      if (offset < first || offset + 4 > end) return 0;
      std::uint32_t value = 0;
      std::memcpy(&value, tx.get_data_ptr() + (offset - first), 4);
      return value;
    };
    const RegisterInfo& batch = info(Reg::batch_cos);
    const bool starts = (word_at(offset_of(Reg::control)) & control_bits::start) ||
                        (word_at(offset_of(Reg::operands) + 20) & control_bits::start) ||
                        (first >= batch.offset && first < batch.end());
    if (starts)
      cov::record_interrupt(irq_bound_, false);
    else if (word_at(offset_of(Reg::status)) & status_bits::done)
      cov::record_interrupt(irq_bound_, true);
  }
  bool irq_bound_;
};

/// The top: endpoints and up to two scenario threads; stops the kernel when both end.
class TlmBench : public sc_core::sc_module {
 public:
  using Scenario = std::function<void(TlmBench&)>;

  TlmBench(sc_core::sc_module_name name, const std::vector<Kind>& kinds, const Config& config,
           const sc_time& period, Scenario main, Scenario second, bool bind_irq = true)
      : sc_module(name), period(period), main_(std::move(main)), second_(std::move(second)) {
    SPECULAR_HAS_PROCESS(TlmBench);
    for (const Kind kind : kinds)
      endpoints.push_back(std::make_unique<Endpoint>(to_string(kind), kind, config, period, bind_irq));
    SC_THREAD(run_main);
    SC_THREAD(run_second);
  }

  sc_time period;
  std::vector<std::unique_ptr<Endpoint>> endpoints;
  Endpoint& at(std::size_t i) { return *endpoints.at(i); }
  Endpoint& operator[](Kind kind) {
    for (auto& e : endpoints)
      if (e->kind == kind) return *e;
    throw std::logic_error("no such endpoint");
  }

  /// Wait until absolute time `when` (no-op if it has passed).
  void until(const sc_time& when) {
    const sc_time now = sc_core::sc_time_stamp();
    if (when > now) wait(when - now);
  }

 private:
  void run_main() {
    main_(*this);
    main_done_ = true;
    if (second_done_) sc_core::sc_stop();
  }
  void run_second() {
    if (second_) second_(*this);
    second_done_ = true;
    if (main_done_) sc_core::sc_stop();
  }
  Scenario main_, second_;
  bool main_done_ = false, second_done_ = false;
};

/// Elaborates the bench (once per process, i.e. once per TEST) and simulates it.
inline void run(const std::vector<Kind>& kinds, TlmBench::Scenario main,
                const Config& config = Config{}, const sc_time& period = sc_time(10, SC_NS),
                TlmBench::Scenario second = {}, bool bind_irq = true) {
  static std::unique_ptr<TlmBench> bench;  // alive until exit, as SystemC wants
  bench = std::make_unique<TlmBench>("bench", kinds, config, period, std::move(main),
                                     std::move(second), bind_irq);
  sc_core::sc_start();
}

}  // namespace tlm_testing
}  // namespace specular
