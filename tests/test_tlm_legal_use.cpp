// Issue 20, "any legal use, every target": lt, pin and rtl behind a TLM-2.0
// base-protocol checker (support/base_protocol_checker.h), driven by an initiator
// that makes the choices the base protocol leaves to it (support/legal_initiator.h):
// b_transport from several threads; nb_transport_fw with BEGIN_REQ at any delay and
// BEGIN_RESP answered TLM_COMPLETED, TLM_UPDATED/END_RESP or TLM_ACCEPTED + END_RESP;
// b and nb mixed in one thread and across threads; bursts (OPERANDS, RESULTS,
// BATCH_COS, BATCH_OUT); debug transport while operations run. Every result is
// compared with Core::run on the same operands; no response other than TLM_OK, no
// protocol breach, no SystemC error (an error throws out of sc_start and fails the test).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "support/legal_use_bench.h"

namespace specular {
namespace {

using namespace tlm_testing;
using sc_core::sc_time;
using sc_core::SC_NS;

constexpr Path every_path[] = {Path::b, Path::nb_completed, Path::nb_updated, Path::nb_accepted};

class LegalUse : public testing::TestWithParam<Target> {
 protected:
  /// Elaborates the bench for this test's target and runs it to the end.
  void run(std::function<void(LegalUseBench&)> setup, int workers, LegalUseBench::Body body) {
    static std::unique_ptr<LegalUseBench> bench;  // alive until exit, as SystemC wants
    bench = std::make_unique<LegalUseBench>("bench", GetParam(), Config{}, sc_time(10, SC_NS));
    bench->start(std::move(setup), workers, std::move(body));
    sc_core::sc_start();
    b = bench.get();
    for (const std::string& failure : b->failures) ADD_FAILURE() << failure;
    for (const std::string& breach : b->checker.violations) ADD_FAILURE() << "protocol: " << breach;
    EXPECT_TRUE(b->checker.idle()) << "an nb transaction was left half way";
  }
  LegalUseBench* b = nullptr;
};

std::vector<std::uint32_t> random_cos(std::mt19937& random, std::size_t count) {
  std::uniform_int_distribution<std::uint32_t> cos(0, 65536);
  std::vector<std::uint32_t> codes(count);
  for (auto& c : codes) c = cos(random);
  return codes;
}

constexpr code_t shared_n = 37;
constexpr std::array<code_t, 3> shared_rgb{255, 140, 9};

void set_shared(LegalUseBench& bench) { bench.set_shared(Path::b, shared_n, shared_rgb); }

// Three initiator threads call b_transport at once, each on its own part of the batch
// window (N, R, G, B shared), so every result is exact whatever the interleaving.
TEST_P(LegalUse, SeveralThreadsCallBTransport) {
  run(set_shared, 3, [](LegalUseBench& bench, int worker) {
    std::mt19937 random(100 + worker);
    for (int round = 0; round < 12; ++round)
      bench.batch(Path::b, Path::b, 64 * worker, random_cos(random, 1 + round % 5), shared_n,
                  shared_rgb);
  });
  EXPECT_EQ(b->compared, 3L * 33 * 3);  // 3 workers × 33 operations × R, G, B
}

// nb_transport_fw with every initiator answer and several BEGIN_REQ delays, for single
// operations (OPERANDS with START, RESULTS) and batches.
TEST_P(LegalUse, NbTransportWithEveryAnswerAndDelay) {
  run(nullptr, 1, [](LegalUseBench& bench, int) {
    std::mt19937 random(7);
    std::uniform_int_distribution<code_t> cos(0, 65536), n(1, 1000), rgb(0, 255);
    const sc_time delays[] = {sc_core::SC_ZERO_TIME, sc_time(3, SC_NS), bench.period * 2.25};
    for (const Path write : every_path)
      for (const Path read : every_path)
        for (const sc_time& delay : delays) {
          if (write == Path::b && read == Path::b) continue;  // not nb
          Operands op;
          op.cos = cos(random);
          op.n = n(random);
          op.rgb = {rgb(random), rgb(random), rgb(random)};
          bench.single(write, read, op, delay);
          bench.set_shared(write, op.n, op.rgb);
          bench.batch(write, read, 3, random_cos(random, 4), op.n, op.rgb, delay);
        }
  });
  EXPECT_EQ(b->compared, 15L * 3 * (3 + 4 * 3));
  EXPECT_GT(b->checker.nb_completed, 15L * 3 * 2);  // the nb accesses went through to their end
}

// One thread mixes b and nb at random, access by access; n and R, G, B change.
TEST_P(LegalUse, MixedBAndNbInOneThread) {
  run(nullptr, 1, [](LegalUseBench& bench, int) {
    std::mt19937 random(11);
    std::uniform_int_distribution<int> path(0, 3);
    std::uniform_int_distribution<code_t> cos(0, 65536), n(1, 1000), rgb(0, 255);
    for (int i = 0; i < 40; ++i) {
      Operands op;
      op.cos = cos(random);
      op.n = n(random);
      op.rgb = {rgb(random), rgb(random), rgb(random)};
      bench.single(every_path[path(random)], every_path[path(random)], op);
      if (i % 4 == 0)
        bench.batch(every_path[path(random)], every_path[path(random)], 1000 - 8 * (i / 4),
                    random_cos(random, 8), op.n, op.rgb);
    }
  });
  EXPECT_EQ(b->compared, 40L * 3 + 10L * 8 * 3);
}

// Four threads, each mixing b and nb at random, on their own parts of the batch window.
TEST_P(LegalUse, SeveralThreadsMixBAndNb) {
  run(set_shared, 4, [](LegalUseBench& bench, int worker) {
    std::mt19937 random(300 + worker);
    std::uniform_int_distribution<int> path(0, 3), delay_ns(0, 25);
    for (int round = 0; round < 10; ++round)
      bench.batch(every_path[path(random)], every_path[path(random)], 100 * worker,
                  random_cos(random, 1 + round % 3), shared_n, shared_rgb,
                  sc_time(delay_ns(random), SC_NS));
  });
  EXPECT_EQ(b->compared, 4L * 3 * (1 + 2 + 3 + 1 + 2 + 3 + 1 + 2 + 3 + 1));
}

// A debugger reads and writes through transport_dbg while another thread runs batches:
// debug access never waits, sees the shared operands, and disturbs no result. On `pin`
// it sees STATUS.busy while the transactor drives the pins; `lt` and `rtl` complete each
// operation inside its call, so they never show busy.
TEST_P(LegalUse, DebugTransportWhileOperationsRun) {
  bool running = true;
  long busy_seen = 0, peeks = 0;
  run(set_shared, 2, [&](LegalUseBench& bench, int worker) {
    if (worker == 0) {
      std::mt19937 random(5);
      for (int round = 0; round < 8; ++round)
        bench.batch(every_path[round % 4], every_path[(round + 1) % 4], 0,
                    random_cos(random, 40), shared_n, shared_rgb);
      running = false;
      return;
    }
    std::uint32_t cos = 0;
    while (running) {
      const sc_time before = sc_core::sc_time_stamp();
      std::uint32_t words[5] = {};
      if (bench.cpu.debug(tlm::TLM_READ_COMMAND, offset_of(Reg::operands), words, 20) != 20)
        bench.fail("debug read of OPERANDS did not return 20 bytes");
      if (words[0] != cos || words[1] != shared_n || words[2] != shared_rgb[0] ||
          words[3] != shared_rgb[1] || words[4] != shared_rgb[2])
        bench.fail("debug read of OPERANDS saw other operands");
      std::uint32_t status = 0;
      bench.cpu.debug(tlm::TLM_READ_COMMAND, offset_of(Reg::status), &status, 4);
      if (status & status_bits::busy) ++busy_seen;
      cos = (cos + 4099) % 65537;
      if (bench.cpu.debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::cos), &cos, 4) != 4)
        bench.fail("debug write of COS refused");
      if (sc_core::sc_time_stamp() != before) bench.fail("debug transport took time");
      ++peeks;
      sc_core::wait(bench.period / 3);
    }
  });
  EXPECT_EQ(b->compared, 8L * 40 * 3);
  EXPECT_GT(peeks, 0);
  if (GetParam() == Target::pin)
    EXPECT_GT(busy_seen, 0);
  else
    EXPECT_EQ(busy_seen, 0);
}

INSTANTIATE_TEST_SUITE_P(Targets, LegalUse, testing::Values(Target::lt, Target::pin, Target::rtl),
                         [](const testing::TestParamInfo<Target>& info) {
                           return std::string(to_string(info.param));
                         });

}  // namespace
}  // namespace specular
