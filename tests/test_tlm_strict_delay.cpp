// The IP under a strict initiator (docs/integration.md §6, issue 29): riscv-vp's memory
// interface passes its quantum keeper's local time as b_transport's `delay`, asserts
// after the call that the returned delay is not smaller, and sets the keeper to it.
//   - every target passes it with Core's bits (pin with PinDelay::keep), and pin with
//     PinDelay::consume is caught by it (the check can fail);
//   - PinDelay::keep waits exactly the operation's latency from the call's simulated
//     time and returns the delay unchanged: the initiator's time grows by the latency
//     once; pins 27 and 35 where the protocol puts them; done_irq at the initiator's time;
//   - for an initiator that does not decouple, keep and consume drive the same pins at
//     the same times.
// Expected times come from the clock period, the set-up rule (start at the first rising
// edge at least T/4 after the call) and the spec's timing table (35 rises 2.5 T after
// the start edge, one operation more every 2 T); expected bits from Core.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "specular/tlm/lt_target.h"
#include "specular/tlm/pin_target.h"
#include "specular/twin/rtl_sync_target.h"
#include "specular/twin/rtl_target.h"
#include "support/signal_log.h"

namespace specular {
namespace {

using sc_core::sc_time;
using sc_core::SC_NS;
using testing_support::SignalLog;

const sc_time period(10, SC_NS);

enum class Kind { lt, pin_keep, pin_consume, rtl, rtl_sync };

std::string kind_name(const testing::TestParamInfo<Kind>& info) {
  switch (info.param) {
    case Kind::lt: return "lt";
    case Kind::pin_keep: return "pin_keep";
    case Kind::pin_consume: return "pin_consume";
    case Kind::rtl: return "rtl";
    case Kind::rtl_sync: return "rtl_sync";
  }
  return "unknown";
}

std::unique_ptr<SpecularTarget> make_target(const char* name, Kind kind) {
  switch (kind) {
    case Kind::lt: return std::make_unique<SpecularLtTarget>(name, Config{}, period);
    case Kind::pin_keep:
      return std::make_unique<SpecularPinTarget>(name, Config{}, period, false, PinDelay::keep);
    case Kind::pin_consume:
      return std::make_unique<SpecularPinTarget>(name, Config{}, period, false, PinDelay::consume);
    case Kind::rtl: return std::make_unique<SpecularRtlTarget>(name, Config{}, period);
    case Kind::rtl_sync: return std::make_unique<SpecularRtlSyncTarget>(name, Config{}, period);
  }
  return nullptr;
}

/// A CPU as riscv-vp's: one thread, a quantum keeper (1 µs), every access through
/// access(), which counts the calls whose delay shrank instead of aborting.
struct StrictCpu : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<StrictCpu, 32> socket{"socket"};
  tlm_utils::tlm_quantumkeeper keeper;
  std::function<void(StrictCpu&)> program;
  std::size_t calls = 0;
  std::size_t shrinks = 0;  ///< riscv-vp's assert(delay >= quantum_keeper.get_local_time()) failed
  struct Call {
    sc_time kernel_before, delay_before, kernel_after, delay_after;
  };
  Call last;  ///< the last access

  StrictCpu(sc_core::sc_module_name name, std::function<void(StrictCpu&)> body)
      : sc_module(name), program(std::move(body)) {
    SPECULAR_HAS_PROCESS(StrictCpu);
    tlm_utils::tlm_quantumkeeper::set_global_quantum(sc_time(1, sc_core::SC_US));
    keeper.reset();
    SC_THREAD(run);
  }

  tlm::tlm_response_status access(tlm::tlm_command command, std::uint64_t address, void* data,
                                  unsigned length) {
    tlm::tlm_generic_payload tx;
    tx.set_command(command);
    tx.set_address(address);
    tx.set_data_ptr(static_cast<unsigned char*>(data));
    tx.set_data_length(length);
    tx.set_streaming_width(0);
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    last.kernel_before = sc_core::sc_time_stamp();
    last.delay_before = keeper.get_local_time();
    sc_time delay = keeper.get_local_time();
    socket->b_transport(tx, delay);
    last.kernel_after = sc_core::sc_time_stamp();
    last.delay_after = delay;
    ++calls;
    if (delay < keeper.get_local_time()) ++shrinks;
    keeper.set(delay);
    if (keeper.need_sync()) keeper.sync();
    EXPECT_TRUE(tx.is_response_ok()) << std::hex << address;
    return tx.get_response_status();
  }
  void write(Reg reg, std::uint32_t value) { access(tlm::TLM_WRITE_COMMAND, offset_of(reg), &value, 4); }
  std::uint32_t read(Reg reg) {
    std::uint32_t value = 0xDEADBEEF;
    access(tlm::TLM_READ_COMMAND, offset_of(reg), &value, 4);
    return value;
  }
  /// The initiator's time: simulated time plus its quantum keeper's offset.
  sc_time now() const { return sc_core::sc_time_stamp() + keeper.get_local_time(); }

 private:
  void run() {
    program(*this);
    sc_core::sc_stop();
  }
};

struct StrictTop : sc_core::sc_module {
  StrictCpu cpu;
  std::unique_ptr<SpecularTarget> target;
  StrictTop(sc_core::sc_module_name name, Kind kind, std::function<void(StrictCpu&)> program)
      : sc_module(name), cpu("cpu", std::move(program)), target(make_target("ip", kind)) {
    cpu.socket.bind(target->socket);
  }
};

StrictTop& elaborate_and_run(Kind kind, std::function<void(StrictCpu&)> program,
                             std::function<void(StrictTop&)> before_start = {}) {
  static std::unique_ptr<StrictTop> top;  // alive until exit, as SystemC wants
  top = std::make_unique<StrictTop>("top", kind, std::move(program));
  if (before_start) before_start(*top);
  sc_core::sc_start();
  return *top;
}

/// Every path that runs an operation, under the strict CPU with instructions between
/// the accesses (local time grows); every result compared with Core.
void every_operation_path(StrictCpu& cpu, std::size_t& compared) {
  const Core core;
  const Operands inputs[] = {{64500, 40, {255, 200, 100}}, {30000, 1, {7, 0, 255}},
                             {65536, 1000, {128, 128, 128}}, {0, 3, {1, 2, 3}}};
  for (const Operands& in : inputs) {  // register by register, polling STATUS
    cpu.keeper.inc(sc_time(13, SC_NS));
    cpu.write(Reg::n, static_cast<std::uint32_t>(in.n));
    cpu.write(Reg::r, static_cast<std::uint32_t>(in.rgb[0]));
    cpu.write(Reg::g, static_cast<std::uint32_t>(in.rgb[1]));
    cpu.write(Reg::b, static_cast<std::uint32_t>(in.rgb[2]));
    cpu.write(Reg::cos, static_cast<std::uint32_t>(in.cos));
    cpu.write(Reg::control, control_bits::start);
    for (int polls = 0; (cpu.read(Reg::status) & status_bits::done) == 0; ++polls) {
      ASSERT_LT(polls, 1000) << "STATUS.done never came";
      cpu.keeper.inc(sc_time(5, SC_NS));
    }
    const Result expected = core.run(in);
    EXPECT_EQ(static_cast<std::int32_t>(cpu.read(Reg::out_r)), expected.out[0]);
    EXPECT_EQ(static_cast<std::int32_t>(cpu.read(Reg::out_g)), expected.out[1]);
    EXPECT_EQ(static_cast<std::int32_t>(cpu.read(Reg::out_b)), expected.out[2]);
    cpu.write(Reg::status, status_bits::done);
    ++compared;
  }
  {  // OPERANDS with START, then RESULTS: two bursts
    const Operands in{41000, 77, {9, 99, 199}};
    std::uint32_t operands[6] = {41000, 77, 9, 99, 199, control_bits::start};
    cpu.keeper.inc(sc_time(21, SC_NS));
    cpu.access(tlm::TLM_WRITE_COMMAND, offset_of(Reg::operands), operands, sizeof operands);
    std::uint32_t out[3] = {};
    cpu.access(tlm::TLM_READ_COMMAND, offset_of(Reg::results), out, sizeof out);
    const Result expected = core.run(in);
    for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(static_cast<std::int32_t>(out[ch]), expected.out[ch]);
    ++compared;
  }
  {  // a batch of four, N, R, G, B shared
    std::uint32_t cos[4] = {65536, 60000, 12345, 1};
    cpu.keeper.inc(sc_time(8, SC_NS));
    cpu.access(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), cos, sizeof cos);
    std::uint32_t out[12] = {};
    cpu.access(tlm::TLM_READ_COMMAND, offset_of(Reg::batch_out), out, sizeof out);
    for (int i = 0; i < 4; ++i) {
      const Result expected = core.run({cos[i], 77, {9, 99, 199}});
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_EQ(static_cast<std::int32_t>(out[3 * i + ch]), expected.out[ch]) << i << "/" << ch;
      ++compared;
    }
  }
}

class StrictInitiator : public testing::TestWithParam<Kind> {};

// lt, rtl and rtl-sync annotate and never wait; pin keeps the delay (PinDelay::keep).
TEST_P(StrictInitiator, NoDelayShrinksAndEveryResultIsCores) {
  std::size_t compared = 0;
  const StrictCpu& cpu =
      elaborate_and_run(GetParam(), [&](StrictCpu& c) { every_operation_path(c, compared); }).cpu;
  // (The program's own ASSERTs end the thread early, so count what it compared.)
  EXPECT_EQ(compared, 9u);
  EXPECT_GT(cpu.calls, 40u);
  EXPECT_EQ(cpu.shrinks, 0u) << "riscv-vp's assert(delay >= local time) would abort";
}

INSTANTIATE_TEST_SUITE_P(EveryTarget, StrictInitiator,
                         testing::Values(Kind::lt, Kind::pin_keep, Kind::rtl, Kind::rtl_sync),
                         kind_name);

// The check is live: pin with PinDelay::consume waits the delay out and returns 0,
// which is legal TLM-2.0 and exactly what the strict initiator refuses.
TEST(StrictInitiatorCheck, PinConsumingTheDelayIsCaught) {
  std::size_t compared = 0;
  const StrictCpu& cpu =
      elaborate_and_run(Kind::pin_consume, [&](StrictCpu& c) { every_operation_path(c, compared); }).cpu;
  EXPECT_EQ(compared, 9u) << "the bits are right all the same";
  EXPECT_GE(cpu.shrinks, 6u) << "each START, the OPERANDS burst and the batch return 0";
}

/// The first rising clock edge at least a quarter period after `t` (set-up of pin 17).
sc_time start_edge(const sc_time& t) {
  return period * std::ceil((t + period / 4) / period);
}

// PinDelay::keep: the call waits from its simulated time to pin 35's rise, no more, and
// returns the delay as it came; the initiator's time therefore grows by the latency
// once. Pins 27 and 35 sit where the protocol puts them relative to the call.
TEST(PinDelayKeep, WaitsExactlyTheLatencyAndReturnsTheDelayUnchanged) {
  struct Seen {
    sc_time t_single, d_single, after_single, t_batch, d_batch, after_batch;
    std::size_t shrinks = 0;
  } seen;
  std::unique_ptr<SignalLog> log;
  std::vector<sc_time> irq_rises;
  elaborate_and_run(
      Kind::pin_keep,
      [&](StrictCpu& cpu) {
        cpu.write(Reg::n, 5);
        cpu.write(Reg::control, control_bits::start);  // the first: resets pin 29 first
        cpu.keeper.sync();
        cpu.keeper.inc(sc_time(237, SC_NS));  // decoupled: 237 ns ahead of simulated time
        cpu.write(Reg::cos, 50000);
        cpu.write(Reg::control, control_bits::start);
        seen.t_single = cpu.last.kernel_before;
        seen.d_single = cpu.last.delay_before;
        seen.after_single = cpu.last.kernel_after;
        EXPECT_EQ(cpu.last.delay_after, cpu.last.delay_before) << "the delay comes back unchanged";
        // Sync, so that done_irq's rise is not merged with the next START's fall (a
        // done/clear pair inside one quantum need not show as a pulse).
        cpu.keeper.sync();
        cpu.keeper.inc(sc_time(101, SC_NS));
        std::uint32_t cos[3] = {1000, 2000, 3000};
        cpu.access(tlm::TLM_WRITE_COMMAND, offset_of(Reg::batch_cos), cos, sizeof cos);
        seen.t_batch = cpu.last.kernel_before;
        seen.d_batch = cpu.last.delay_before;
        seen.after_batch = cpu.last.kernel_after;
        EXPECT_EQ(cpu.last.delay_after, cpu.last.delay_before);
        seen.shrinks = cpu.shrinks;
        cpu.keeper.sync();
        sc_core::wait(period * 10);  // the clock's tail, and done_irq at the initiator's time
      },
      [&](StrictTop& top) {
        auto& pin = static_cast<SpecularPinTarget&>(*top.target);
        log = std::make_unique<SignalLog>(
            "log", SignalLog::Watched{{"27", &pin.harness.pin27_start}, {"35", &pin.harness.pin35_done}});
        pin.on_done_irq([&](bool level) {
          if (level) irq_rises.push_back(sc_core::sc_time_stamp());
        });
      });
  EXPECT_EQ(seen.shrinks, 0u);
  EXPECT_EQ(seen.d_single, sc_time(237, SC_NS)) << "the test's premise: decoupled calls";
  EXPECT_EQ(seen.d_batch, sc_time(101, SC_NS));

  // One operation: start edge E after the call's simulated time, 35 at E + 2.5 T, and the
  // call returns then: it waited the latency and nothing else.
  const sc_time e1 = start_edge(seen.t_single);
  EXPECT_EQ(seen.after_single, e1 + period * 2.5);
  // A batch of three: 35 at E + 2.5 T, + 2 T, + 2 T; the call returns at the last.
  const sc_time e2 = start_edge(seen.t_batch);
  EXPECT_EQ(seen.after_batch, e2 + period * 6.5);

  const std::vector<sc_time> starts = log->rises("27");
  const std::vector<sc_time> dones = log->rises("35");
  ASSERT_EQ(starts.size(), 5u) << "warm-up, single, batch of three";
  ASSERT_EQ(dones.size(), 5u);
  EXPECT_EQ(starts[1], e1);
  EXPECT_EQ(dones[1], e1 + period * 2.5);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(starts[2 + i], e2 + period * (2.0 * i)) << i;
    EXPECT_EQ(dones[2 + i], e2 + period * (2.5 + 2.0 * i)) << i;
  }
  // done_irq rises at the initiator's time of the end: the call's return plus its delay.
  ASSERT_EQ(irq_rises.size(), 3u);
  EXPECT_EQ(irq_rises[1], seen.after_single + seen.d_single);
  EXPECT_EQ(irq_rises[2], seen.after_batch + seen.d_batch);
}

// For an initiator that waits out each delay itself (no decoupling), keep and consume
// drive the same pins at the same times: two pin targets, one per policy, run the same
// program side by side.
TEST(PinDelayKeep, SameWaveformsAsConsumeForAnInitiatorThatDoesNotDecouple) {
  struct Side : sc_core::sc_module {
    tlm_utils::simple_initiator_socket<Side, 32> socket{"socket"};
    SpecularPinTarget target;
    std::vector<std::uint32_t> results;
    SignalLog log;
    Side(sc_core::sc_module_name name, PinDelay policy)
        : sc_module(name),
          target("ip", Config{}, period, false, policy),
          log("log", {{"27", &target.harness.pin27_start},
                      {"28", &target.harness.pin28()},
                      {"29", &target.harness.pin29_reset_n},
                      {"30", &target.harness.pin30_load_n},
                      {"31", &target.harness.pin31_load_r},
                      {"32", &target.harness.pin32_load_g},
                      {"33", &target.harness.pin33_load_b},
                      {"35", &target.harness.pin35_done}}) {
      SPECULAR_HAS_PROCESS(Side);
      socket.bind(target.socket);
      SC_THREAD(program);
    }
    void transport(tlm::tlm_command command, Reg reg, std::uint32_t* words, unsigned count) {
      tlm::tlm_generic_payload tx;
      tx.set_command(command);
      tx.set_address(offset_of(reg));
      tx.set_data_ptr(reinterpret_cast<unsigned char*>(words));
      tx.set_data_length(4 * count);
      tx.set_streaming_width(0);
      sc_time delay = sc_core::SC_ZERO_TIME;
      socket->b_transport(tx, delay);
      wait(delay);
      EXPECT_TRUE(tx.is_response_ok());
    }
    void program() {
      std::uint32_t operands[6] = {64500, 40, 255, 200, 100, control_bits::start};
      transport(tlm::TLM_WRITE_COMMAND, Reg::operands, operands, 6);
      wait(33, SC_NS);
      operands[0] = 100;
      operands[1] = 999;
      transport(tlm::TLM_WRITE_COMMAND, Reg::operands, operands, 6);
      std::uint32_t cos[3] = {65536, 3, 40000};
      transport(tlm::TLM_WRITE_COMMAND, Reg::batch_cos, cos, 3);
      std::uint32_t out[9];
      transport(tlm::TLM_READ_COMMAND, Reg::batch_out, out, 9);
      results.assign(out, out + 9);
      wait(100, SC_NS);
    }
  };
  struct Top : sc_core::sc_module {
    Side consume{"consume", PinDelay::consume};
    Side keep{"keep", PinDelay::keep};
    explicit Top(sc_core::sc_module_name name) : sc_module(name) {}
  };
  static std::unique_ptr<Top> top;
  top = std::make_unique<Top>("top");
  sc_core::sc_start(sc_time(2, sc_core::SC_US));
  const auto& a = top->consume.log.changes();
  const auto& b = top->keep.log.changes();
  EXPECT_GT(a.size(), 50u) << "the pins moved";
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].signal, b[i].signal) << i;
    EXPECT_EQ(a[i].time, b[i].time) << i << " pin " << a[i].signal;
    EXPECT_EQ(a[i].value, b[i].value) << i << " pin " << a[i].signal;
  }
  EXPECT_EQ(top->consume.results, top->keep.results);
  const Core core;
  for (int i = 0; i < 3; ++i)
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_EQ(static_cast<std::int32_t>(top->keep.results.at(3 * i + ch)),
                core.run({std::vector<code_t>{65536, 3, 40000}[i], 999, {255, 200, 100}}).out[ch]);
}

}  // namespace
}  // namespace specular
