// libFuzzer target: transaction SEQUENCES on every target (issue 20). Each input is
// decoded into 1–3 initiator threads, each with its own list of accesses — batches
// through its own part of the batch window, single operations through OPERANDS and
// RESULTS, operand changes, debug reads, pauses — and each access travels by
// b_transport or by nb_transport_fw with any answer a legal initiator may give to
// BEGIN_RESP (TLM_COMPLETED, TLM_UPDATED/END_RESP, TLM_ACCEPTED + END_RESP) and any
// BEGIN_REQ delay. Probes add single accesses of any width a bus may issue — 1, 2, 4
// or 8 bytes, aligned or not, lengths no register takes (0, 3, 6, 12) — with any
// streaming width (0, the length, above it, below it) to registers, holes, windows and
// addresses outside the map. The same threads run against `lt`, `pin` and `rtl` side
// by side, each behind the tests' base-protocol checker (tests/support/). Findings:
//   - a SystemC error (e.g. two writers of a pin: it throws out of sc_start), a crash,
//     undefined behaviour (ASan/UBSan);
//   - a protocol breach seen by the checker, an nb transaction left half way;
//   - a response other than TLM_OK_RESPONSE to a batch, single, shared or debug access;
//   - a probe answered otherwise than docs/integration.md says (sections 2–4: holes and
//     misalignment → address error; other lengths, 8 bytes off a doubleword offset,
//     sub-word window writes and streaming width in 1..length-1 → burst error; writes to
//     read-only rows → command error; out-of-range values → generic error, value kept);
//   - a probe read whose bytes differ from those bytes of the words as expected: the
//     documented constants (ID, VERSION, CONFIG, BATCH_CAPACITY, PIN19_H, PIN20_A,
//     CONTROL = 0), the operands as written, and with one thread every other word as a
//     debug read gives it just before the access;
//   - lt, pin and rtl answering a probe differently (status always; data where it
//     cannot depend on how the threads interleave);
//   - a result different from Core::run: batch results exactly; a single operation's
//     results exactly with one thread, else equal to Core on one of the input's cos
//     codes (N, R, G, B are then shared by all threads);
//   - a debug read of N, R, G, B that differs from what was written.
//
// The design is elaborated once in LLVMFuzzerInitialize; each input wakes the worker
// threads, and when they are done the driver thread pauses the kernel (sc_pause).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "specular/report_ids.h"
#include "support/legal_use_bench.h"
#include "fuzz_bytes.h"

// libsystemc refers to sc_main; libFuzzer's main() runs instead, so it is never called.
extern "C" int sc_main(int, char**) { return 0; }

namespace {

using namespace specular;
using namespace specular::tlm_testing;
using sc_core::sc_time;
using sc_core::SC_NS;

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz_tlm_sequences: %s\n", what.c_str());
  std::abort();
}

using specular_fuzz::Bytes;

constexpr std::uint32_t region_words = 64;  ///< each thread's part of the batch window
constexpr std::size_t max_actions = 32;     ///< per input, over all threads

/// One probe: a single access of a chosen width and streaming width.
struct Probe {
  tlm::tlm_command command = tlm::TLM_READ_COMMAND;
  std::uint64_t address = 0;
  unsigned length = 4;
  unsigned streaming_width = 0;
  std::array<unsigned char, 16> data{};  ///< written bytes (writes)
};

struct Action {
  enum Kind : std::uint8_t { batch, single, shared, debug, pause, probe, kinds } kind;
  Path write, read;
  sc_time delay;
  std::vector<std::uint32_t> cos;  ///< batch: the codes; single: one code
  std::uint32_t first = 0;         ///< batch: word within the thread's region
  code_t n = 1;                    ///< shared
  std::array<code_t, 3> rgb{};     ///< shared
  Probe access;                    ///< probe
};

struct Plan {
  int threads = 1;
  code_t n = 1;
  std::array<code_t, 3> rgb{};
  std::vector<std::vector<Action>> actions;  ///< per thread
  std::set<std::uint32_t> cos_used;          ///< every cos code of the input
};

Path path_of(std::uint8_t b) { return static_cast<Path>(b % static_cast<int>(Path::count)); }

// ---- the documented access rules (docs/integration.md sections 2–4), written apart
// from the target's decoder: which row holds an address, what a bus check answers.

const RegisterInfo* row_at(std::uint64_t address) {
  for (const RegisterInfo& row : register_map)
    if (address >= row.offset && address < row.end()) return &row;
  return nullptr;
}

/// The answer of the bus checks (address, alignment, length, streaming width, window
/// end, the second word of 8 bytes), before any register says anything.
tlm::tlm_response_status bus_rule(std::uint64_t address, unsigned length, unsigned streaming) {
  const RegisterInfo* row = row_at(address & ~std::uint64_t{3});
  if (row == nullptr) return tlm::TLM_ADDRESS_ERROR_RESPONSE;  // hole or outside the map
  const bool sub_word = length == 1 || length == 2;
  if (address % (sub_word ? length : 4) != 0) return tlm::TLM_ADDRESS_ERROR_RESPONSE;
  if (length == 0 || (!sub_word && length % 4 != 0)) return tlm::TLM_BURST_ERROR_RESPONSE;
  const bool single = row->words == 1;
  if (single && length > 4 && (length != 8 || address % 8 != 0)) return tlm::TLM_BURST_ERROR_RESPONSE;
  if (streaming != 0 && streaming < length) return tlm::TLM_BURST_ERROR_RESPONSE;
  if (!single && !sub_word && (address - row->offset) / 4 + length / 4 > row->words)
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;  // a burst past its window
  if (single && length == 8 && row_at(address + 4) == nullptr)
    return tlm::TLM_ADDRESS_ERROR_RESPONSE;  // the second word is a hole
  return tlm::TLM_OK_RESPONSE;
}

bool is_operand(Reg reg) {
  return reg == Reg::cos || reg == Reg::n || reg == Reg::r || reg == Reg::g || reg == Reg::b;
}

/// Every single register, the holes around them, window words (first and last) and
/// addresses outside the map, as word addresses; a probe adds a lane to some.
const std::vector<std::uint64_t>& probe_places() {
  static const std::vector<std::uint64_t> places = [] {
    std::vector<std::uint64_t> p;
    for (const RegisterInfo& row : register_map)
      if (row.words == 1) p.push_back(row.offset);
    for (std::uint64_t hole : {0x01C, 0x034, 0x03C, 0x04C, 0x074, 0x07C, 0x098, 0x0AC, 0x7000, 0x7FFC})
      p.push_back(hole);
    for (std::uint64_t w = 0; w < 6; ++w) p.push_back(offset_of(Reg::operands) + 4 * w);
    for (std::uint64_t w = 0; w < 3; ++w) p.push_back(offset_of(Reg::results) + 4 * w);
    for (std::uint64_t a : {0x1000u, 0x1008u, 0x1000u + 4 * (batch_capacity - 1), 0x4000u, 0x4010u,
                            0x4000u + 4 * (3 * batch_capacity - 1)})
      p.push_back(a);
    for (std::uint64_t a : {std::uint64_t{map_size}, std::uint64_t{0x1'0000'0020}}) p.push_back(a);
    return p;
  }();
  return places;
}

/// Whether a probe write's answer is the same whatever other threads do meanwhile
/// (a refusal before any busy check, or STATUS's W1C), and it leaves the operands and
/// the operation alone; with one thread, CONTROL and the operands may be written too.
bool write_allowed(const Probe& p, int threads) {
  if (bus_rule(p.address, p.length, p.streaming_width) != tlm::TLM_OK_RESPONSE) return true;
  const RegisterInfo& row = *row_at(p.address & ~std::uint64_t{3});
  if (row.words > 1) return row.access == Access::read_only || p.length < 4;
  if (row.access == Access::read_only || row.reg == Reg::status) return true;
  return threads == 1;  // CONTROL, COS, N, R, G, B (8 bytes: the first word decides)
}

Probe decode_probe(Bytes& in, int threads) {
  Probe p;
  const std::uint8_t place = in.u8(), shape = in.u8(), stream = in.u8();
  p.address = probe_places()[place % probe_places().size()];
  static constexpr unsigned lengths[16] = {1, 1, 1, 2, 2, 2, 4, 4, 4, 8, 8, 8, 0, 3, 6, 12};
  p.length = lengths[shape & 15];
  const unsigned lane = (shape >> 4) & 3;
  if (shape & 0x40)
    p.address += lane;  // any lane: misaligned unless it happens to fit
  else if (p.length == 1 || p.length == 2)
    p.address += (lane * p.length) % 4;  // naturally aligned inside the word
  switch (stream & 3) {
    case 0: p.streaming_width = 0; break;  // no streaming (riscv-vp)
    case 1: p.streaming_width = p.length; break;
    case 2: p.streaming_width = p.length + 1 + (stream >> 2) % 8; break;
    default: p.streaming_width = p.length > 1 ? 1 + (stream >> 2) % (p.length - 1) : 0; break;
  }
  if (shape & 0x80) {
    p.command = tlm::TLM_WRITE_COMMAND;
    // Mostly small values (in range for N, R, G, B, COS), sometimes any bytes.
    p.data[0] = in.u8();
    if (stream & 0x20) p.data[1] = in.u8();
    if (stream & 0x40)
      for (std::size_t i = 2; i < p.data.size(); ++i) p.data[i] = in.u8();
    if (!(stream & 0x40)) std::memcpy(&p.data[4], &p.data[0], 4);  // 8 bytes: both words alike
    if (!write_allowed(p, threads)) p.command = tlm::TLM_READ_COMMAND;
  }
  return p;
}

Plan decode(Bytes in) {
  Plan plan;
  plan.threads = 1 + in.u8() % 3;  // Driver::max_threads
  plan.n = 1 + in.u24() % 1000;
  plan.rgb = {in.u8(), in.u8(), in.u8()};
  plan.actions.resize(plan.threads);
  for (std::size_t i = 0; i < max_actions && !in.empty(); ++i) {
    Action a;
    const std::uint8_t head = in.u8();
    const int thread = head % plan.threads;
    a.kind = static_cast<Action::Kind>((head >> 2) % Action::kinds);
    if (a.kind == Action::shared && plan.threads > 1) a.kind = Action::debug;  // exactness
    const std::uint8_t paths = in.u8();
    a.write = path_of(paths);
    a.read = path_of(paths >> 4);
    a.delay = sc_time(in.u8() % 40, SC_NS);
    switch (a.kind) {
      case Action::batch: {
        const std::uint32_t k = 1 + in.u8() % 8;
        a.first = in.u8() % (region_words - k + 1);
        for (std::uint32_t j = 0; j < k; ++j) a.cos.push_back(in.u24() % 65537);
        break;
      }
      case Action::single: a.cos.push_back(in.u24() % 65537); break;
      case Action::shared:
        a.n = 1 + in.u24() % 1000;
        a.rgb = {in.u8(), in.u8(), in.u8()};
        break;
      case Action::probe: a.access = decode_probe(in, plan.threads); break;
      default: break;
    }
    for (const std::uint32_t c : a.cos) plan.cos_used.insert(c);
    plan.actions[thread].push_back(std::move(a));
  }
  return plan;
}

class Driver : public sc_core::sc_module {
 public:
  explicit Driver(sc_core::sc_module_name name) : sc_module(name) {
    SPECULAR_HAS_PROCESS(Driver);
    for (const Target kind : {Target::lt, Target::pin, Target::rtl})
      benches.push_back(std::make_unique<LegalUseBench>(to_string(kind), kind, Config{}, period));
    SC_THREAD(run);
    // Worker threads live as long as the design: the socket's nb-to-b threads are
    // spawned as their children, and a child that outlives a finished dynamic parent
    // leaves SystemC's name bookkeeping behind (LeakSanitizer reports it).
    for (auto& bench : benches)
      for (int t = 0; t < max_threads; ++t)
        sc_core::sc_spawn([this, b = bench.get(), t] { serve(*b, t); },
                          (std::string(bench->basename()) + "_worker" + std::to_string(t)).c_str());
  }

  void start(const Plan& plan) {
    plan_ = &plan;
    go_.notify(sc_core::SC_ZERO_TIME);
  }

  const sc_time period{10, SC_NS};
  std::vector<std::unique_ptr<LegalUseBench>> benches;

  /// What a target answered to one probe, for comparing lt, pin and rtl.
  struct Seen {
    tlm::tlm_response_status status;
    bool data_comparable;  ///< the bytes read cannot depend on the threads' interleaving
    std::array<unsigned char, 16> data;
    std::string what;
  };
  std::vector<std::array<std::vector<Seen>, 3>> seen;  ///< per bench, per thread

 private:
  void run() {
    for (;;) {
      wait(go_);
      seen.assign(benches.size(), {});
      // The same starting state on every target whatever earlier inputs did: one
      // operation on COS = 0 and the input's N, R, G, B (OUT_* and the inspection
      // registers), then STATUS.done and .error cleared (ERROR_ADDRESS too).
      for (auto& bench : benches) {
        std::uint32_t words[6] = {0, static_cast<std::uint32_t>(plan_->n),
                                  static_cast<std::uint32_t>(plan_->rgb[0]),
                                  static_cast<std::uint32_t>(plan_->rgb[1]),
                                  static_cast<std::uint32_t>(plan_->rgb[2]), control_bits::start};
        bench->ok(Path::b, tlm::TLM_WRITE_COMMAND, offset_of(Reg::operands), words, sizeof words);
        std::uint32_t clear = status_bits::done | status_bits::error;
        bench->ok(Path::b, tlm::TLM_WRITE_COMMAND, offset_of(Reg::status), &clear, 4);
      }
      running_ = static_cast<int>(benches.size()) * plan_->threads;
      work_.notify(sc_core::SC_ZERO_TIME);
      while (running_ > 0) wait(ended_);
      sc_core::sc_pause();
    }
  }

  void serve(LegalUseBench& bench, int thread) {
    for (;;) {
      sc_core::wait(work_);
      if (thread < plan_->threads) worker(bench, thread);
    }
  }

  void worker(LegalUseBench& bench, int thread) {
    code_t n = plan_->n;
    std::array<code_t, 3> rgb = plan_->rgb;
    code_t cos = 0;  // known with one thread only (others start operations)
    for (const Action& a : plan_->actions[thread]) {
      switch (a.kind) {
        case Action::batch:
          bench.batch(a.write, a.read, thread * region_words + a.first, a.cos, n, rgb, a.delay);
          break;
        case Action::single: {
          Operands op;
          op.cos = a.cos.front();
          op.n = n;
          op.rgb = rgb;
          const bool exact = plan_->threads == 1;
          const auto out = bench.single(a.write, a.read, op, a.delay, exact);
          cos = op.cos;
          if (!exact) {
            bool known = false;
            for (const std::uint32_t c : plan_->cos_used) {
              op.cos = c;
              const Result r = bench.core.run(op);
              known |= out[0] == r.out[0] && out[1] == r.out[1] && out[2] == r.out[2];
            }
            if (!known) bench.fail("single operation: results of no operation of this input");
          }
          break;
        }
        case Action::shared:
          n = a.n;
          rgb = a.rgb;
          bench.set_shared(a.write, n, rgb);
          break;
        case Action::debug: {
          std::uint32_t words[4] = {};
          if (bench.cpu.debug(tlm::TLM_READ_COMMAND, offset_of(Reg::n), words, 16) != 16)
            bench.fail("debug read of N, R, G, B short");
          if (words[0] != n || words[1] != rgb[0] || words[2] != rgb[1] || words[3] != rgb[2])
            bench.fail("debug read of N, R, G, B: not what was written");
          break;
        }
        case Action::probe: probe(bench, thread, a, n, rgb, cos); break;
        default: sc_core::wait(a.delay + sc_time(1, SC_NS)); break;
      }
    }
    if (--running_ == 0) ended_.notify(sc_core::SC_ZERO_TIME);
  }

  /// One probe: its answer against the documented rule, the bytes of a read against
  /// the words as expected; with one thread, the operands follow an accepted write.
  void probe(LegalUseBench& bench, int thread, const Action& a, code_t& n,
             std::array<code_t, 3>& rgb, code_t& cos) {
    const Probe& p = a.access;
    const bool alone = plan_->threads == 1;
    const std::uint64_t word_address = p.address & ~std::uint64_t{3};
    // Words the access covers when it is accepted (a window burst may take three).
    const unsigned words = p.length <= 4 ? 1 : std::min(3u, p.length / 4);
    // The value of an operand register as this thread knows it.
    const auto operand = [&](Reg reg) -> std::optional<std::uint32_t> {
      if (reg == Reg::n) return static_cast<std::uint32_t>(n);
      if (reg >= Reg::r && reg <= Reg::b)
        return static_cast<std::uint32_t>(rgb[index_of(reg) - index_of(Reg::r)]);
      if (reg == Reg::cos && alone) return static_cast<std::uint32_t>(cos);
      return std::nullopt;
    };
    // Expected words: documented constants and known operands (the same on every
    // target whatever the interleaving), else with one thread a debug read now.
    std::array<std::optional<std::uint32_t>, 3> expected;
    bool comparable = true;
    for (unsigned w = 0; w < words; ++w) {
      const std::uint64_t address = word_address + 4 * w;
      const RegisterInfo* row = row_at(address);
      if (row == nullptr) continue;
      Reg reg = row->reg;
      if (reg == Reg::operands) {
        static constexpr Reg aliases[6] = {Reg::cos, Reg::n, Reg::r, Reg::g, Reg::b, Reg::control};
        reg = aliases[(address - row->offset) / 4];
      }
      switch (reg) {
        case Reg::id:
        case Reg::version:
        case Reg::config:
        case Reg::batch_capacity:
        case Reg::pin19_h:
        case Reg::pin20_a: expected[w] = info(reg).reset; break;  // Config{}'s documented values
        case Reg::control: expected[w] = 0; break;                // START is self-clearing
        default:
          if (is_operand(reg)) expected[w] = operand(reg);
          break;
      }
      if (!expected[w] && alone) {
        std::uint32_t value = 0;
        if (bench.cpu.debug(tlm::TLM_READ_COMMAND, address, &value, 4) == 4) expected[w] = value;
      }
      if (!expected[w]) comparable = false;
    }

    // The documented answer, and what an accepted write does to the operands.
    tlm::tlm_response_status rule = bus_rule(p.address, p.length, p.streaming_width);
    std::array<std::optional<std::uint32_t>, 3> stored;  // operand words after the write
    if (rule == tlm::TLM_OK_RESPONSE && p.command == tlm::TLM_WRITE_COMMAND) {
      const bool sub_word = p.length < 4;
      for (unsigned w = 0; w < words && rule == tlm::TLM_OK_RESPONSE; ++w) {
        const RegisterInfo& row = *row_at(word_address + 4 * w);
        std::uint32_t value = 0;
        if (sub_word) {
          // STATUS and CONTROL see the bytes written, zeros elsewhere; operands merge.
          unsigned char bytes[4] = {};
          if (is_operand(row.reg)) {
            const std::uint32_t old = operand(row.reg).value_or(0);  // known: write_allowed
            std::memcpy(bytes, &old, 4);
          }
          std::memcpy(bytes + p.address % 4, p.data.data(), p.length);
          std::memcpy(&value, bytes, 4);
        } else {
          std::memcpy(&value, &p.data[4 * w], 4);
        }
        if (row.access == Access::read_only)
          rule = tlm::TLM_COMMAND_ERROR_RESPONSE;
        else if (row.words > 1)
          rule = tlm::TLM_BURST_ERROR_RESPONSE;  // sub-word into a window (write_allowed)
        else if ((row.reg == Reg::cos && value > 65536) || (row.reg == Reg::n && (value < 1 || value > 1000)) ||
                 (row.reg >= Reg::r && row.reg <= Reg::b && value > 255) ||
                 (row.reg == Reg::control && (value & ~control_bits::start) != 0))
          rule = tlm::TLM_GENERIC_ERROR_RESPONSE;  // out of range: refused, value kept
        else if (is_operand(row.reg))
          stored[w] = value;
      }
    }

    std::array<unsigned char, 16> data = p.data;
    if (p.command == tlm::TLM_READ_COMMAND) data.fill(0xA5);
    const Path path = p.command == tlm::TLM_READ_COMMAND ? a.read : a.write;
    ++bench.accesses;
    const tlm::tlm_response_status status =
        bench.cpu.transport(path, p.command, p.address, data.data(), p.length, a.delay, p.streaming_width);

    char what[160];
    std::snprintf(what, sizeof what, "probe %s of %u byte(s) at 0x%llx, streaming width %u, %s",
                  p.command == tlm::TLM_READ_COMMAND ? "read" : "write", p.length,
                  static_cast<unsigned long long>(p.address), p.streaming_width, to_string(path));
    if (status != rule)
      bench.fail(std::string(what) + ": answered " + name_of(status) + ", documented " + name_of(rule));
    if (status == tlm::TLM_OK_RESPONSE && p.command == tlm::TLM_READ_COMMAND) {
      for (unsigned i = 0; i < p.length; ++i) {
        const unsigned at = static_cast<unsigned>(p.address - word_address) + i;
        if (!expected[at / 4]) continue;
        unsigned char bytes[4];
        std::memcpy(bytes, &*expected[at / 4], 4);
        if (data[i] != bytes[at % 4])
          bench.fail(std::string(what) + ": byte " + std::to_string(i) + " read 0x" +
                     LegalUseBench::hex(data[i]) + ", expected 0x" + LegalUseBench::hex(bytes[at % 4]) +
                     " (byte " + std::to_string(at % 4) + " of word 0x" +
                     LegalUseBench::hex(*expected[at / 4]) + ")");
      }
    }
    if (status == tlm::TLM_OK_RESPONSE && p.command == tlm::TLM_WRITE_COMMAND) {
      for (unsigned w = 0; w < words; ++w) {
        if (!stored[w]) continue;
        const Reg reg = row_at(word_address + 4 * w)->reg;
        if (reg == Reg::cos) cos = *stored[w];
        else if (reg == Reg::n) n = *stored[w];
        else rgb[index_of(reg) - index_of(Reg::r)] = *stored[w];
      }
    }
    Seen s{status, comparable && p.command == tlm::TLM_READ_COMMAND && status == tlm::TLM_OK_RESPONSE,
           data, what};
    seen[bench_index(bench)][thread].push_back(s);
  }

  std::size_t bench_index(const LegalUseBench& bench) const {
    for (std::size_t i = 0; i < benches.size(); ++i)
      if (benches[i].get() == &bench) return i;
    return 0;
  }

  static std::string name_of(tlm::tlm_response_status status) {
    tlm::tlm_generic_payload named;
    named.set_response_status(status);
    return named.get_response_string();
  }

  static constexpr int max_threads = 3;
  const Plan* plan_ = nullptr;
  sc_core::sc_event go_, work_, ended_;
  int running_ = 0;
};

Driver* driver = nullptr;

/// The checker's entry checks that the probes break on purpose, as third-party
/// initiators do (riscv-vp leaves the streaming width at 0; a length of 0 tests the
/// refusal): IEEE 1666 breaches by the initiator, which the IP must answer, not the
/// target's. Every other breach stays a finding.
bool initiators_own(const std::string& breach) {
  for (const char* own : {": streaming width is 0", ": data length is 0"}) {
    const std::string tail(own);
    if (breach.size() >= tail.size() && breach.compare(breach.size() - tail.size(), tail.size(), tail) == 0)
      return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  // The pin device's own protocol reports are findings too: every access is legal.
  for (const char* type : report::protocol_types)
    sc_core::sc_report_handler::set_actions(type, sc_core::SC_DISPLAY | sc_core::SC_ABORT);
  driver = new Driver("fuzz");  // lives until exit, as SystemC wants
  // Elaborate and run the initialisation now: otherwise the first input's go_
  // notification, made before the first sc_start, is lost and that input never runs
  // (a replayed finding passed unseen when it came first).
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Plan plan = decode(Bytes(data, size));
  driver->start(plan);
  sc_core::sc_start();
  for (auto& bench : driver->benches) {
    const std::string name = bench->name();
    for (const std::string& failure : bench->failures) finding(name + ": " + failure);
    for (const std::string& breach : bench->checker.violations)
      if (!initiators_own(breach)) finding(name + ": protocol: " + breach);
    if (!bench->checker.idle()) finding(name + ": an nb transaction was left half way");
  }
  // lt, pin and rtl answer every probe alike, and read the same bytes where they may.
  const auto& seen = driver->seen;
  for (std::size_t b = 1; b < seen.size(); ++b)
    for (int t = 0; t < 3; ++t) {
      if (seen[b][t].size() != seen[0][t].size()) finding("probe counts differ between targets");
      for (std::size_t i = 0; i < seen[0][t].size(); ++i) {
        const auto& first = seen[0][t][i];
        const auto& other = seen[b][t][i];
        const std::string names = driver->benches[0]->name() + std::string(" and ") +
                                  driver->benches[b]->name() + ": " + first.what;
        if (first.status != other.status)
          finding(names + ": answered " + std::to_string(first.status) + " and " +
                  std::to_string(other.status));
        if (first.data_comparable && other.data_comparable && first.data != other.data)
          finding(names + ": read different bytes");
      }
    }
  return 0;
}
