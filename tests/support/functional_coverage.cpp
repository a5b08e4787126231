// The functional coverage bins (issue 37), declared here and nowhere else, and the
// recorder the test support code calls (functional_coverage.h says how hits travel from
// the many test processes to scripts/verify/functional_coverage.py's report).
#include "functional_coverage.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <stdexcept>

namespace specular {
namespace testing_support {
namespace coverage {
namespace {

const char* const transports[] = {"b", "nb", "dbg"};
const char* const widths[] = {"1", "2", "4", "8", "burst"};

bool is_read_only(const RegisterInfo& row) { return row.access == Access::read_only; }

/// docs/tlm.md's debug transport: word by word, it reads every mapped word and writes
/// the RW storage only (COS, N, R, G, B, OPERANDS words 0-4, BATCH_COS).
bool debug_serves(std::uint64_t address, bool write) {
  const RegisterInfo* row = decode(address);
  if (row == nullptr) return false;
  if (!write) return true;
  if (row->reg == Reg::operands) return (address - row->offset) / 4 < 5;  // CONTROL: not storage
  return row->access == Access::read_write;
}

/// Why no legal access of `bytes` bytes at `row` through `transport` exists (docs/tlm.md's
/// rules), or "" when one does.
std::string no_legal_access(const RegisterInfo& row, bool write, const std::string& width,
                            const std::string& transport) {
  const bool window = row.words > 1;
  const unsigned bytes = width == "burst" ? 12 : static_cast<unsigned>(std::stoul(width));
  if (transport == "dbg") {
    if (bytes < 4) return "the debug transport serves whole words only";
    for (unsigned i = 0; i < bytes; i += 4)
      if (!debug_serves(row.offset + i, write))
        return write ? "the debug transport writes the RW storage only (COS, N, R, G, B, OPERANDS 0-4, BATCH_COS)"
                     : "the debug transport stops at the hole after the register";
    return "";
  }
  if (write && is_read_only(row)) return "read-only: every write is refused";
  if (!window && width == "burst") return "a single register takes at most 8 bytes on the bus";
  if (window && write && bytes < 4) return "a window refuses sub-word writes on the bus";
  if (!window && bytes == 8) {
    const RegisterInfo* second = decode(row.offset + 4);
    if (row.offset % 8 != 0 || second == nullptr || (write && is_read_only(*second)))
      return write ? "8 bytes on the bus need a doubleword offset and a writable register after it"
                   : "8 bytes on the bus need a doubleword offset and a register after it";
  }
  return "";
}

std::vector<Bin> declare() {
  std::vector<Bin> bins;
  auto add = [&](std::string name, std::string what, std::string ignore = "") {
    bins.push_back({std::move(name), std::move(what), std::move(ignore)});
  };
  // ---- the operand space ----
  add("cos/zero", "COS code 0 (cos = 0: log2 0 := -F)");
  add("cos/one_lsb", "COS code 1, the smallest positive cosine");
  add("cos/max", "COS code 2^F = 1.0 (65536 for U1.16)");
  for (int k = 0; k <= 16; ++k)
    add("cos/rom5_segment_" + std::to_string(k),
        "COS code with its leading one at bit " + std::to_string(k) +
            " (ROM 5 segment: the exponent multiplexer 3's normaliser finds)");
  add("reg9/clamped_zero", "register 9 after pass 2 read back as 0 (clamp's saturation edge)");
  add("reg9/negative", "register 9 after pass 2 negative (literal: below the clamp)");
  add("reg9/positive", "register 9 after pass 2 positive (inside the range)");
  add("n/1", "n = 1, the smallest");
  add("n/2", "n = 2");
  add("n/power_of_two", "n = 4, 8, ..., 512");
  add("n/1000", "n = 1000, the largest");
  add("n/other", "any other n in 3..999");
  add("rgb/0", "an intensity of 0");
  add("rgb/1", "an intensity of 1");
  add("rgb/255", "an intensity of 255, the largest");
  // ---- every normalisation x saturation x constants setting ----
  for (Normalisation nm : {Normalisation::patent, Normalisation::energy, Normalisation::none,
                           Normalisation::device_energy})
    for (Saturation s : {Saturation::clamp, Saturation::literal})
      for (Constants c : {Constants::patent, Constants::minimax_half, Constants::minimax})
        add(policy_bin(nm, s, c), "a target built with this policy",
            nm == Normalisation::device_energy && s == Saturation::literal && c == Constants::patent
                ? "refused at construction (K*A below multiplier 39's format, docs/design.md)"
                : "");
  // ---- register accesses: register x read/write x width x legal/illegal x transport ----
  for (const RegisterInfo& row : register_map)
    for (const char* rw : {"read", "write"})
      for (const char* width : widths)
        for (const char* legality : {"legal", "illegal"})
          for (const char* transport : transports) {
            const bool legal = std::string(legality) == "legal";
            const bool write = std::string(rw) == "write";
            const std::string ignore = legal ? no_legal_access(row, write, width, transport) : "";
            add(std::string("access/") + row.name + "/" + rw + "/" + width + "/" + legality + "/" +
                    transport,
                std::string(rw) + " of " + width + " byte(s) at " + row.name + ", " + legality +
                    ", through " + transport + "_transport",
                ignore);
          }
  for (const char* rw : {"read", "write"})
    for (const char* transport : transports)
      add(std::string("access/unmapped/") + rw + "/illegal/" + transport,
          std::string("a ") + rw + " of an unmapped offset through " + transport + "_transport");
  // ---- the interrupt and reset ----
  for (const char* mask : {"enabled", "masked"})
    for (const char* order : {"acknowledged_before_next_start", "acknowledged_after_next_start"})
      add(std::string("interrupt/") + mask + "/" + order,
          std::string(mask == std::string("enabled")
                          ? "done_irq bound to the platform's interrupt line"
                          : "done interrupt masked: done_irq left unbound (the map has no mask "
                            "register; the SoC's controller does not take the line), STATUS.done polled") +
              (std::string(order) == "acknowledged_before_next_start"
                   ? "; STATUS.done acknowledged (1 written) before the next START"
                   : "; the next START arrives while STATUS.done is still set (acknowledged after it)"));
  add("reset/during_operation", "pin 29 (reset) asserted while an operation is in flight");
  return bins;
}

class Recorder {
 public:
  static Recorder& get() {
    static Recorder r;
    return r;
  }
  bool on() const { return !folder_.empty(); }
  void hit(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (declared_.empty())
      for (const Bin& b : all_bins()) declared_.emplace(b.name, true);
    if (declared_.find(name) == declared_.end())
      throw std::logic_error("functional coverage: bin '" + name +
                             "' is not declared in tests/support/functional_coverage.cpp");
    ++hits_[name];
  }
  ~Recorder() {
    if (!on() || hits_.empty()) return;
    std::random_device random;
    std::ostringstream path;
    path << folder_ << "/fcov-" << getpid() << "-" << std::hex << random() << ".tsv";
    std::ofstream out(path.str());
    for (const auto& [name, count] : hits_) out << name << '\t' << count << '\n';
  }

 private:
  Recorder() {
    const char* folder = std::getenv("SPECULAR_FUNCTIONAL_COVERAGE");
    if (folder != nullptr) folder_ = folder;
  }
  std::string folder_;
  std::mutex mutex_;
  std::map<std::string, bool> declared_;
  std::map<std::string, unsigned long long> hits_;
};

std::uint64_t little_endian(const unsigned char* data, unsigned length) {
  std::uint64_t v = 0;
  for (unsigned i = 0; i < length && i < 8; ++i) v |= std::uint64_t{data[i]} << (8 * i);
  return v;
}

}  // namespace

const std::vector<Bin>& all_bins() {
  static const std::vector<Bin> bins = declare();
  return bins;
}

bool enabled() { return Recorder::get().on(); }

void hit(const std::string& name) {
  if (enabled()) Recorder::get().hit(name);
}

std::vector<std::string> cos_bins(std::uint64_t code, int cos_frac_bits) {
  std::vector<std::string> bins;
  if (code == 0) return {"cos/zero"};
  if (code == 1) bins.push_back("cos/one_lsb");
  if (code == (std::uint64_t{1} << cos_frac_bits)) bins.push_back("cos/max");
  int top = 63;
  while (((code >> top) & 1u) == 0) --top;
  if (top <= 16) bins.push_back("cos/rom5_segment_" + std::to_string(top));
  return bins;
}

std::vector<std::string> n_bins(std::uint64_t n) {
  if (n == 1) return {"n/1"};
  if (n == 2) return {"n/2"};
  if (n == 1000) return {"n/1000"};
  if (n >= 4 && n <= 512 && (n & (n - 1)) == 0) return {"n/power_of_two"};
  if (n >= 3 && n <= 999) return {"n/other"};
  return {};
}

std::vector<std::string> rgb_bins(std::uint64_t value) {
  if (value == 0) return {"rgb/0"};
  if (value == 1) return {"rgb/1"};
  if (value == 255) return {"rgb/255"};
  return {};
}

std::string policy_bin(Normalisation normalisation, Saturation saturation, Constants constants) {
  return std::string("policy/") + to_string(normalisation) + "/" + to_string(saturation) + "/" +
         to_string(constants);
}

std::string width_class(unsigned length) {
  if (length == 1 || length == 2 || length == 4 || length == 8) return std::to_string(length);
  return "burst";
}

void record_policy(const Config& config) {
  if (!enabled()) return;
  hit(policy_bin(config.normalisation, config.saturation, config.constants));
}

void record_access(std::uint64_t offset, bool write, unsigned length, bool legal, Transport transport,
                   const unsigned char* data, int cos_frac_bits) {
  if (!enabled()) return;
  const char* t = transports[static_cast<int>(transport)];
  const RegisterInfo* row = decode(offset & ~std::uint64_t{3});
  const char* rw = write ? "write" : "read";
  if (row == nullptr) {
    hit(std::string("access/unmapped/") + rw + "/illegal/" + t);
    return;
  }
  hit(std::string("access/") + row->name + "/" + rw + "/" + width_class(length) + "/" +
      (legal ? "legal" : "illegal") + "/" + t);
  if (!legal || data == nullptr || length > 8) return;
  if (!write && (row->reg == Reg::reg9_pass2_lo) && length >= 4) {
    const std::uint64_t v = little_endian(data, length);
    record_reg9(length == 8 ? static_cast<std::int64_t>(v) : static_cast<std::int32_t>(v));
    return;
  }
  if (!write || offset % 4 != 0 || length < 4) return;
  const std::uint64_t value = little_endian(data, 4);
  std::vector<std::string> bins;
  if (row->reg == Reg::cos) bins = cos_bins(value, cos_frac_bits);
  else if (row->reg == Reg::n) bins = n_bins(value);
  else if (row->reg == Reg::r || row->reg == Reg::g || row->reg == Reg::b) bins = rgb_bins(value);
  for (const std::string& b : bins) hit(b);
}

void record_operation(const Operands& operands, int cos_frac_bits) {
  if (!enabled()) return;
  for (const std::string& b : cos_bins(static_cast<std::uint64_t>(operands.cos), cos_frac_bits)) hit(b);
  for (const std::string& b : n_bins(static_cast<std::uint64_t>(operands.n))) hit(b);
  for (code_t v : operands.rgb)
    for (const std::string& b : rgb_bins(static_cast<std::uint64_t>(v))) hit(b);
}

void record_reg9(std::int64_t code) {
  if (!enabled()) return;
  hit(code == 0 ? "reg9/clamped_zero" : code < 0 ? "reg9/negative" : "reg9/positive");
}

void record_interrupt(bool enabled_irq, bool acknowledged_before_next_start) {
  if (!enabled()) return;
  hit(std::string("interrupt/") + (enabled_irq ? "enabled" : "masked") + "/" +
      (acknowledged_before_next_start ? "acknowledged_before_next_start"
                                      : "acknowledged_after_next_start"));
}

void record_reset_during_operation() { hit("reset/during_operation"); }

}  // namespace coverage
}  // namespace testing_support
}  // namespace specular
