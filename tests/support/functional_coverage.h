// Functional coverage of the stimulus space (issue 37): which operand classes, policy
// settings, register accesses, interrupt orders and resets the suite drives. The bins are
// declared in one place, functional_coverage.cpp (all_bins()); the test support code
// records hits through the functions below. Recording is off unless the environment
// variable SPECULAR_FUNCTIONAL_COVERAGE names a folder: then each test process writes its
// hits at exit to a file of its own there (fcov-<pid>-<random>.tsv, "group/bin<TAB>count"),
// and scripts/verify/functional_coverage.py sums every process's file into the report, failing on
// an unhit bin. Unset, every function returns after one cached test: no cost to the suite.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "specular/core.h"
#include "specular/format.h"
#include "specular/tlm/register_map.h"

namespace specular {
namespace testing_support {
namespace coverage {

struct Bin {
  std::string name;    ///< "group/bin"
  std::string what;    ///< what a hit means
  std::string ignore;  ///< non-empty: cannot be hit, with the reason (not required)
};

/// Every declared bin, in report order (the one place they are declared).
const std::vector<Bin>& all_bins();

/// True when SPECULAR_FUNCTIONAL_COVERAGE is set (read once per process).
bool enabled();

/// One hit of a declared bin; an undeclared name throws std::logic_error naming it.
void hit(const std::string& name);

// ---- classifiers (pure: the bins a value falls in) ------------------------------------
std::vector<std::string> cos_bins(std::uint64_t code, int cos_frac_bits);
std::vector<std::string> n_bins(std::uint64_t n);
std::vector<std::string> rgb_bins(std::uint64_t value);
std::string policy_bin(Normalisation normalisation, Saturation saturation, Constants constants);
std::string width_class(unsigned length);

// ---- recorders (no-ops unless enabled()) ----------------------------------------------
void record_policy(const Config& config);
enum class Transport { b, nb, dbg };
/// One access as the target answered it: the register decoded from the offset (none:
/// "unmapped"), the command, the length, legal = TLM_OK_RESPONSE. For a legal write of
/// COS, N, R, G or B the written value also hits its operand class.
void record_access(std::uint64_t offset, bool write, unsigned length, bool legal, Transport transport,
                   const unsigned char* data, int cos_frac_bits = 16);
/// Register 9 after pass 2 as read back (REG9_PASS2_LO/HI): clamped to 0, negative, positive.
void record_reg9(std::int64_t code);
/// One operation's operands (cos, n, R, G, B) and register 9 after pass 2.
void record_operation(const Operands& operands, int cos_frac_bits = 16);
void record_interrupt(bool enabled, bool acknowledged_before_next_start);
void record_reset_during_operation();

}  // namespace coverage
}  // namespace testing_support
}  // namespace specular
