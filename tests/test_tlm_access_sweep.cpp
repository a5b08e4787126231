// A directed sweep of the register accesses (issue 37, functional coverage's access/
// bins): every row of the C++ register map, and an unmapped offset, x read/write x 1, 2,
// 4, 8 bytes and a 12-byte burst x legal/illegal, through b_transport, nb_transport or
// transport_dbg, one TEST per row and transport. Each access goes through the
// base-protocol checker (which records the bins) to an `lt` target, and its outcome is
// asserted against what the map and docs/tlm.md's rules say, computed here: the response
// (or the debug transport's byte count), the data of a legal read (the map's reset
// values), and every mapped word of the target afterwards (a legal write stores what the
// rules say, a refused access changes only STATUS.error, its cause and ERROR_ADDRESS, the
// debug transport nothing but the storage it writes). The same rules say which bins no
// access can hit; a test checks that they are exactly the bins functional_coverage.cpp
// declares impossible.
//
// The same sweep runs on `axi` (the RTL IP behind its AXI4-Lite transactor, issue 46) for
// every row the IP has (not the batch windows: holes there, BATCH_CAPACITY 0), with axi's
// rules of docs/rtl_ip.md: a payload AXI4-Lite cannot carry is refused before the bus
// (lt's response, every word as it was), and the debug transport writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/tlm/register_map.h"
#include "support/functional_coverage.h"
#include "support/functional_coverage_child.h"
#include "support/legal_use_bench.h"

namespace {

using namespace specular;
using namespace specular::tlm_testing;
namespace cov = specular::testing_support::coverage;

enum class Via { b, nb, dbg };
const char* const via_names[] = {"b", "nb", "dbg"};
const char* const width_names[] = {"1", "2", "4", "8", "burst"};
constexpr unsigned widths[] = {1, 2, 4, 8, 12};  // "burst": three words
constexpr std::size_t unmapped_row = register_count;  // the parameter for a hole

/// The first word-aligned offset that no row decodes (0x01C, after ERROR_ADDRESS).
std::uint32_t a_hole() {
  for (std::uint32_t offset = 0; offset < map_size; offset += 4)
    if (decode(offset) == nullptr) return offset;
  return map_size;
}

// ---- the rules of docs/tlm.md, written from the map ------------------------------------

/// The single register behind a mapped word (OPERANDS aliases COS ... CONTROL).
Reg register_behind(std::uint32_t address) {
  const RegisterInfo* row = decode(address);
  if (row->reg == Reg::operands) return operand_register((address - row->offset) / 4);
  return row->reg;
}

/// A value each register takes (docs/tlm.md: COS 0..65536, N 1..1000, R/G/B 0..255;
/// STATUS 0 clears nothing, CONTROL 0 starts nothing), different for each width's write
/// (`salt`) so that every write changes what it writes; BATCH_COS words differ per word.
std::uint32_t good_value(std::uint32_t address, unsigned salt) {
  const RegisterInfo* row = decode(address);
  if (row->reg == Reg::batch_cos) return 1000 * ((address - row->offset) / 4 + 1) + salt;
  switch (register_behind(address)) {
    case Reg::cos: return 50000 + 1000 * salt;
    case Reg::n: return 20 + salt;
    case Reg::r: return 200 + 10 * salt;
    case Reg::g: return 100 + salt;
    case Reg::b: return 50 + salt;
    default: return 0;
  }
}

/// A value the register refuses (the examples of docs/tlm.md's error table).
std::uint32_t bad_value(std::uint32_t address) {
  const RegisterInfo* row = decode(address);
  if (row->reg == Reg::batch_cos) return 65537;
  switch (register_behind(address)) {
    case Reg::cos: return 65537;
    case Reg::n: return 0;
    case Reg::r:
    case Reg::g:
    case Reg::b: return 256;
    case Reg::control: return 2;  // an undefined bit
    default: return 0;
  }
}

/// docs/tlm.md's ranges, for the sweep's own check that a legal write's value is legal.
bool in_range(Reg reg, std::uint32_t value) {
  switch (reg) {
    case Reg::cos: return value <= 65536;
    case Reg::n: return value >= 1 && value <= 1000;
    case Reg::r:
    case Reg::g:
    case Reg::b: return value <= 255;
    case Reg::control: return (value & ~control_bits::defined) == 0;
    default: return true;
  }
}

/// The debug transport serves the word at `address`: it reads every mapped word and
/// writes the RW storage only (COS, N, R, G, B, OPERANDS words 0-4, BATCH_COS).
bool debug_serves(std::uint64_t address, bool write) {
  const RegisterInfo* row = decode(address);
  if (row == nullptr) return false;
  if (!write) return true;
  if (row->reg == Reg::operands) return (address - row->offset) / 4 < 5;  // CONTROL: not storage
  return row->access == Access::read_write;
}

/// One access of the sweep and the outcome the rules give it.
struct Plan {
  std::string impossible;  ///< non-empty: no access hits this bin, and why
  std::uint64_t address = 0;
  unsigned length = 0;
  bool disable_a_byte = false;  ///< a byte-enable array with byte 0 disabled
  bool bad_values = false;      ///< write values the registers refuse
  // bus
  tlm::tlm_response_status status = tlm::TLM_OK_RESPONSE;
  ErrorCause cause = ErrorCause::none;
  std::uint64_t error_address = 0;
  // debug
  unsigned debug_bytes = 0;
};

Plan refused(std::uint64_t address, unsigned length, tlm::tlm_response_status status, ErrorCause cause,
             std::uint64_t error_address) {
  Plan p;
  p.address = address;
  p.length = length;
  p.status = status;
  p.cause = cause;
  p.error_address = error_address;
  return p;
}

/// Whether `target` refuses `p`'s payload before any register sees it: on axi, a shape
/// AXI4-Lite cannot carry (a disabled byte, a misaligned access, a length a row does not
/// take), except a burst past a window whose end is a hole, which the RTL refuses.
bool refused_before_the_bus(const Plan& p, Target target) {
  if (target != Target::axi || p.status == tlm::TLM_OK_RESPONSE) return false;
  if (p.cause == ErrorCause::read_only) return false;
  if (p.cause == ErrorCause::address && p.address % 4 == 0 && decode(p.error_address) == nullptr)
    return false;  // a runaway burst, refused by the RTL at the window's end
  return true;
}

/// The access that hits bin (row, write, width, legal, via), or why none can.
Plan plan(std::size_t row_index, bool write, unsigned width, bool legal, Via via,
          Target target = Target::lt) {
  Plan p;
  if (target == Target::axi && via == Via::dbg && write) {  // axi: debug writes are refused
    if (legal) {
      p.impossible = "axi refuses every debug write";
      return p;
    }
    p.length = widths[width];
    p.address = row_index == unmapped_row ? a_hole() : register_map[row_index].offset;
    p.debug_bytes = 0;
    return p;
  }
  if (row_index == unmapped_row) {  // only access/unmapped/<rw>/illegal/<via>
    p = refused(a_hole(), 4, tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, a_hole());
    return p;
  }
  const RegisterInfo& row = register_map[row_index];
  const bool window = row.words > 1;
  const bool read_only = row.access == Access::read_only;
  const std::uint32_t offset = row.offset;
  const unsigned length = widths[width];
  if (via == Via::dbg) {
    if (legal) {
      if (length < 4) {
        p.impossible = "the debug transport serves whole words only";
        return p;
      }
      for (unsigned i = 0; i < length; i += 4)
        if (!debug_serves(offset + i, write)) {
          p.impossible = write ? "the debug transport writes the RW storage only"
                               : "the debug transport stops at the hole after the register";
          return p;
        }
      p.address = offset;
      p.length = length;
      p.debug_bytes = length;
      return p;
    }
    // refused: a sub-word length, a misaligned address, or (a word write) a refused value
    p.length = length;
    p.address = length < 4 ? offset : offset + 2;
    if (write && length == 4) {
      p.address = offset;
      p.bad_values = true;
    }
    p.debug_bytes = 0;
    return p;
  }
  if (legal) {
    if (write && read_only) {
      p.impossible = "read-only: every write is refused";
      return p;
    }
    if (!window && length == 12) {
      p.impossible = "a single register takes at most 8 bytes on the bus";
      return p;
    }
    if (window && write && length < 4) {
      p.impossible = "a window refuses sub-word writes on the bus";
      return p;
    }
    if (!window && length == 8) {
      const RegisterInfo* second = decode(offset + 4);
      if (offset % 8 != 0 || second == nullptr || (write && second->access == Access::read_only)) {
        p.impossible = write ? "8 bytes on the bus need a doubleword offset and a writable register after it"
                             : "8 bytes on the bus need a doubleword offset and a register after it";
        return p;
      }
    }
    // sub-word reads at the word's last lanes, sub-word writes at its first
    p.address = offset + (write ? 0 : 4 - length % 4) % 4;
    p.length = length;
    return p;
  }
  switch (length) {
    case 1:
      p = refused(offset, 1, tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE, ErrorCause::byte_enable, offset);
      p.disable_a_byte = true;
      return p;
    case 2: return refused(offset + 1, 2, tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, offset + 1);
    case 4:
      if (write && read_only)
        return refused(offset, 4, tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCause::read_only, offset);
      return refused(offset + 2, 4, tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, offset + 2);
    case 8:
      if (window)  // a burst running past its window: an address error at the window's end
        return refused(row.end() - 4, 8, tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, row.end());
      return refused(offset + 2, 8, tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, offset + 2);
    default:
      if (window)
        return refused(row.end() - 8, 12, tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, row.end());
      return refused(offset, 12, tlm::TLM_BURST_ERROR_RESPONSE, ErrorCause::burst, offset);
  }
}

std::string bin_name(std::size_t row_index, bool write, unsigned width, bool legal, Via via) {
  const char* rw = write ? "write" : "read";
  const char* v = via_names[static_cast<int>(via)];
  if (row_index == unmapped_row) return std::string("access/unmapped/") + rw + "/illegal/" + v;
  return std::string("access/") + register_map[row_index].name + "/" + rw + "/" + width_names[width] + "/" +
         (legal ? "legal" : "illegal") + "/" + v;
}

// ---- the rules say which bins no access hits: exactly those declared impossible ----------

TEST(AccessSweepBins, TheBinsNoAccessCanHitAreExactlyThoseDeclaredImpossible) {
  std::map<std::string, std::string> declared;
  for (const cov::Bin& bin : cov::all_bins())
    if (bin.name.rfind("access/", 0) == 0) declared[bin.name] = bin.ignore;
  std::size_t checked = 0;
  for (std::size_t row = 0; row < register_count; ++row)
    for (bool write : {false, true})
      for (unsigned width = 0; width < 5; ++width)
        for (bool legal : {true, false})
          for (Via via : {Via::b, Via::nb, Via::dbg}) {
            const std::string name = bin_name(row, write, width, legal, via);
            ASSERT_EQ(declared.count(name), 1u) << name;
            const Plan p = plan(row, write, width, legal, via);
            EXPECT_EQ(p.impossible.empty(), declared[name].empty())
                << name << ": the rules say '" << p.impossible << "', the declaration '" << declared[name] << "'";
            ++checked;
          }
  EXPECT_EQ(checked + 6, declared.size());  // and the unmapped reads and writes, every one possible
  for (const char* rw : {"read", "write"})
    for (const char* v : via_names)
      EXPECT_EQ(declared.at(std::string("access/unmapped/") + rw + "/illegal/" + v), "");
}

// ---- the sweep ---------------------------------------------------------------------------

using Words = std::map<std::uint32_t, std::uint32_t>;  ///< byte offset -> word, every mapped word

/// What every mapped word reads after construction with the default Config (the map's
/// reset column; OPERANDS and RESULTS alias their registers).
Words reset_words(Target target = Target::lt) {
  Words words;
  for (const RegisterInfo& row : register_map)
    for (std::uint32_t i = 0; i < row.words; ++i) words[row.offset + 4 * i] = reset_of_word(row, i);
  if (target == Target::axi) words[offset_of(Reg::batch_capacity)] = 0;  // docs/decisions.md: no windows
  return words;
}

std::uint32_t load_word(const unsigned char* bytes) {
  std::uint32_t v;
  std::memcpy(&v, bytes, 4);
  return v;
}

class Sweep {
 public:
  Sweep(LegalUseBench& bench, Via via) : bench_(bench), via_(via) {}

  /// Every mapped word, through the debug transport, unrecorded (axi: no batch windows).
  Words snapshot() {
    bench_.checker.record_coverage = false;
    Words words;
    for (const RegisterInfo& row : register_map) {
      if (!on_target(row)) continue;
      std::vector<std::uint32_t> data(row.words);
      const unsigned done = bench_.cpu.debug(tlm::TLM_READ_COMMAND, row.offset, data.data(), 4 * row.words);
      EXPECT_EQ(done, 4 * row.words) << row.name;
      for (std::uint32_t i = 0; i < row.words; ++i) words[row.offset + 4 * i] = data[i];
    }
    bench_.checker.record_coverage = true;
    return words;
  }

  /// Writes 1 to STATUS.error (clears it, its cause and ERROR_ADDRESS), unrecorded.
  void clear_error() {
    bench_.checker.record_coverage = false;
    std::uint32_t w1c = status_bits::error;
    EXPECT_EQ(bench_.cpu.transport(Path::b, tlm::TLM_WRITE_COMMAND, offset_of(Reg::status), &w1c, 4),
              tlm::TLM_OK_RESPONSE);
    bench_.checker.record_coverage = true;
  }

  /// Sets COS, N, R, G, B through the debug transport, unrecorded, to values no write of
  /// the sweep uses, COS and N with a byte above the lowest set (a one-byte write must
  /// keep it), so that the batch window's operations compute something other than zero.
  void set_operands() {
    bench_.checker.record_coverage = false;
    std::uint32_t values[5] = {0x0123, 300, 10, 11, 12};
    if (bench_.kind == Target::axi)  // axi refuses debug writes: the bus, as a CPU would
      EXPECT_EQ(bench_.cpu.transport(Path::b, tlm::TLM_WRITE_COMMAND, offset_of(Reg::operands), values, 20),
                tlm::TLM_OK_RESPONSE);
    else
      EXPECT_EQ(bench_.cpu.debug(tlm::TLM_WRITE_COMMAND, offset_of(Reg::cos), values, 20), 20u);
    bench_.checker.record_coverage = true;
  }

  /// The access of one bin, and every check of its outcome.
  void run(std::size_t row_index, bool write, unsigned width, bool legal) {
    const Plan p = plan(row_index, write, width, legal, via_, bench_.kind);
    const std::string bin = bin_name(row_index, write, width, legal, via_);
    if (!p.impossible.empty()) return;
    SCOPED_TRACE(bin);
    const Words before = snapshot();
    // the data: what a legal write stores (or an illegal one offers), else a pattern
    std::vector<unsigned char> data(p.length, 0xA5);
    if (write) {
      const unsigned count = p.length / 4 + 2;  // the words the access touches, and one more
      std::vector<unsigned char> words(4 * count);
      const std::uint64_t first = p.address & ~std::uint64_t{3};
      for (unsigned i = 0; i < count; ++i) {
        const std::uint64_t a = first + 4 * i;
        std::uint32_t v = 0;
        if (decode(a) != nullptr) v = p.bad_values ? bad_value(a) : good_value(static_cast<std::uint32_t>(a), width);
        std::memcpy(words.data() + 4 * i, &v, 4);
      }
      std::memcpy(data.data(), words.data() + (p.address - first), p.length);
    }
    const Words expected = legal ? after_legal(p, write, data, before) : after_refusal(p, before);
    unsigned char enables[1] = {TLM_BYTE_DISABLED};
    const tlm::tlm_command command = write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND;
    if (via_ == Via::dbg) {
      EXPECT_EQ(bench_.cpu.debug(command, p.address, data.data(), p.length), p.debug_bytes);
    } else {
      const tlm::tlm_response_status status =
          bench_.cpu.transport(via_ == Via::b ? Path::b : Path::nb_accepted, command, p.address, data.data(),
                               p.length, sc_core::SC_ZERO_TIME, LegalInitiator::streaming_width_of_length,
                               p.disable_a_byte ? enables : nullptr, p.disable_a_byte ? 1 : 0);
      EXPECT_EQ(status, p.status);
    }
    if (legal && !write) {  // the bytes the map's reset values give (no write came before)
      const Words reset = reset_words(bench_.kind);
      const std::uint64_t first = p.address & ~std::uint64_t{3};
      const unsigned count = p.length / 4 + 2;
      std::vector<unsigned char> bytes(4 * count);
      for (unsigned i = 0; i < count; ++i) {
        const std::uint32_t v = reset.count(first + 4 * i) ? reset.at(first + 4 * i) : 0;
        std::memcpy(bytes.data() + 4 * i, &v, 4);
      }
      EXPECT_EQ(0, std::memcmp(data.data(), bytes.data() + (p.address - first), p.length)) << "read data";
    }
    expect_words(expected, "after the access");
    if (!legal && via_ != Via::dbg && !refused_before_the_bus(p, bench_.kind)) {
      clear_error();
      expect_words(before, "after STATUS.error's clear");
    }
  }

  void expect_words(const Words& expected, const char* when) {
    const Words now = snapshot();
    int shown = 0;
    for (const auto& [address, value] : expected)
      if (now.count(address) != 0 && now.at(address) != value && shown++ < 8)
        ADD_FAILURE() << when << ": word 0x" << std::hex << address << " reads 0x" << now.at(address)
                      << ", the rules say 0x" << value;
  }


 private:
  /// Whether the target has `row` (axi: no batch windows).
  bool on_target(const RegisterInfo& row) const {
    return bench_.kind != Target::axi || (row.reg != Reg::batch_cos && row.reg != Reg::batch_out);
  }

  /// A refused access changes STATUS.error, its cause and ERROR_ADDRESS (the bus), or
  /// nothing (the debug transport).
  Words after_refusal(const Plan& p, const Words& before) const {
    Words w = before;
    if (via_ == Via::dbg || refused_before_the_bus(p, bench_.kind)) return w;
    std::uint32_t& status = w[offset_of(Reg::status)];
    status = (status & ~status_bits::cause_mask) | status_bits::error |
             (static_cast<std::uint32_t>(p.cause) << status_bits::cause_shift);
    w[offset_of(Reg::error_address)] = static_cast<std::uint32_t>(p.error_address);
    return w;
  }

  /// A legal read changes nothing; a legal write stores its bytes in the registers it
  /// covers (a sub-word write merges into an operand register, STATUS and CONTROL see
  /// zeros elsewhere and were written 0), seen at every address aliasing them; a
  /// BATCH_COS write runs one operation per word (Core's results: BATCH_OUT, OUT_*,
  /// RESULTS and the inspection registers of the last, STATUS.done).
  Words after_legal(const Plan& p, bool write, const std::vector<unsigned char>& data, const Words& before) const {
    Words w = before;
    if (!write) return w;
    const std::uint64_t first = p.address & ~std::uint64_t{3};
    std::vector<Operands> operations;
    for (std::uint64_t a = first; a < p.address + p.length; a += 4) {
      const std::uint32_t address = static_cast<std::uint32_t>(a);
      unsigned char bytes[4];
      const Reg reg = register_behind(address);
      const bool merges = reg != Reg::status && reg != Reg::control;
      const std::uint32_t old = merges ? before.at(address) : 0;
      std::memcpy(bytes, &old, 4);
      const unsigned lo = static_cast<unsigned>(std::max<std::uint64_t>(a, p.address) - a);
      const unsigned hi = static_cast<unsigned>(std::min<std::uint64_t>(a + 4, p.address + p.length) - a);
      std::memcpy(bytes + lo, data.data() + (a + lo - p.address), hi - lo);
      const std::uint32_t value = load_word(bytes);
      EXPECT_TRUE(in_range(reg, value)) << "the sweep's own legal write of 0x" << std::hex << value;
      const RegisterInfo* row = decode(address);
      if (row->reg == Reg::batch_cos) {
        w[address] = value;
        if (via_ == Via::dbg) continue;  // the debug transport never starts an operation
        Operands op;
        op.cos = value;
        op.n = before.at(offset_of(Reg::n));
        op.rgb = {before.at(offset_of(Reg::r)), before.at(offset_of(Reg::g)), before.at(offset_of(Reg::b))};
        operations.push_back(op);
        const std::uint32_t out = offset_of(Reg::batch_out) + 12 * ((address - row->offset) / 4);
        const Result result = bench_.core.run(op);
        for (int ch = 0; ch < 3; ++ch) w[out + 4 * ch] = static_cast<std::uint32_t>(result.out[ch]);
        continue;
      }
      if (reg == Reg::status || reg == Reg::control) continue;  // 0: clears nothing, starts nothing
      w[offset_of(reg)] = value;
      const std::uint32_t operands = offset_of(Reg::operands);
      for (std::uint32_t i = 0; i < operand_words; ++i)
        if (operand_register(i) == reg) w[operands + 4 * i] = value;
    }
    if (!operations.empty()) {
      const Result last = bench_.core.run(operations.back());
      for (int ch = 0; ch < 3; ++ch) {
        w[offset_of(result_register(ch))] = static_cast<std::uint32_t>(last.out[ch]);
        w[offset_of(Reg::results) + 4 * ch] = static_cast<std::uint32_t>(last.out[ch]);
      }
      w[offset_of(Reg::reg1)] = static_cast<std::uint32_t>(last.reg1);
      w[offset_of(Reg::reg9_pass1_lo)] = static_cast<std::uint32_t>(last.reg9_pass1);
      w[offset_of(Reg::reg9_pass1_hi)] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(last.reg9_pass1) >> 32);
      w[offset_of(Reg::reg9_pass2_lo)] = static_cast<std::uint32_t>(last.reg9_pass2);
      w[offset_of(Reg::reg9_pass2_hi)] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(last.reg9_pass2) >> 32);
      w[offset_of(Reg::rom38_k)] = static_cast<std::uint32_t>(last.rom38_k);
      w[offset_of(Reg::norm39)] = static_cast<std::uint32_t>(last.norm39);
      w[offset_of(Reg::status)] |= status_bits::done;
    }
    return w;
  }

  LegalUseBench& bench_;
  Via via_;
};

struct Param {
  std::size_t row;
  Via via;
  Target target = Target::lt;
};

std::string name_of(const Param& param) {
  const std::string row = param.row == unmapped_row ? "UNMAPPED" : register_map[param.row].name;
  return row + "_" + via_names[static_cast<int>(param.via)] + (param.target == Target::axi ? "_axi" : "");
}
std::string param_name(const ::testing::TestParamInfo<Param>& info) { return name_of(info.param); }
// ctest's test names carry the parameter as gtest prints it: its name, not its bytes.
void PrintTo(const Param& param, std::ostream* os) { *os << name_of(param); }

std::vector<Param> every_row_and_transport() {
  std::vector<Param> params;
  for (std::size_t row = 0; row <= unmapped_row; ++row)
    for (Via via : {Via::b, Via::nb, Via::dbg}) params.push_back({row, via});
  return params;
}

/// axi: every row the IP has (the batch windows are holes there), b and dbg (nb reaches
/// the same b_transport through the socket's conversion, already swept on lt).
std::vector<Param> every_ip_row_on_axi() {
  std::vector<Param> params;
  for (std::size_t row = 0; row <= unmapped_row; ++row) {
    if (row < unmapped_row && (register_map[row].reg == Reg::batch_cos || register_map[row].reg == Reg::batch_out))
      continue;
    for (Via via : {Via::b, Via::dbg}) params.push_back({row, via, Target::axi});
  }
  return params;
}

class AccessSweep : public ::testing::TestWithParam<Param> {};

TEST_P(AccessSweep, EveryAccessIsAnsweredAsTheMapSays) {
  const Param param = GetParam();
  static std::unique_ptr<LegalUseBench> owner;  // alive until exit, as SystemC wants
  owner = std::make_unique<LegalUseBench>("bench", param.target, Config{}, sc_core::sc_time(10, sc_core::SC_NS));
  LegalUseBench& bench = *owner;
  int accesses = 0;
  bench.start(
      [&](LegalUseBench& b) {
        Sweep sweep(b, param.via);
        sweep.expect_words(reset_words(param.target), "after construction (the map's reset values)");
        for (bool write : {false, true}) {
          if (write) sweep.set_operands();
          for (unsigned width = 0; width < 5; ++width)
            for (bool legal : {true, false}) {
              if (param.row == unmapped_row && (legal || width != 2)) continue;
              sweep.run(param.row, write, width, legal);
              accesses += plan(param.row, write, width, legal, param.via, param.target).impossible.empty();
            }
        }
      },
      0, {});
  sc_core::sc_start();
  EXPECT_GT(accesses, 0);
  EXPECT_TRUE(bench.checker.violations.empty()) << bench.checker.violations.front();
  EXPECT_TRUE(bench.checker.idle());
}

// What a sweep test records (run as a child with the recording on): each bin its plan
// can hit, once — its snapshots and clean-ups pass unrecorded — and no other access bin.
TEST(AccessSweepRecording, ATestHitsExactlyItsPlannedBinsOnce) {
  for (const Param param : {Param{index_of(Reg::cos), Via::nb}, Param{index_of(Reg::operands), Via::dbg}}) {
    std::map<std::string, long> want;
    for (bool write : {false, true})
      for (unsigned width = 0; width < 5; ++width)
        for (bool legal : {true, false})
          if (plan(param.row, write, width, legal, param.via).impossible.empty())
            want[bin_name(param.row, write, width, legal, param.via)] = 1;
    const auto hits = testing_support::hits_of_child(
        "EveryRowAndTransport/AccessSweep.EveryAccessIsAnsweredAsTheMapSays/" + name_of(param));
    EXPECT_EQ(testing_support::hits_under(hits, "access/"), want) << name_of(param);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryRowAndTransport, AccessSweep, ::testing::ValuesIn(every_row_and_transport()),
                         param_name);
INSTANTIATE_TEST_SUITE_P(EveryIpRowOnAxi, AccessSweep, ::testing::ValuesIn(every_ip_row_on_axi()), param_name);

}  // namespace
