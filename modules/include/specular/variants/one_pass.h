/// \file
/// One pass, two ROMs (issue 26, docs/variants/one_pass.md): the patent's competitor that
/// spends silicon instead of time. Pass 1 and pass 2 run in series, each on its own ROM 5,
/// multiplier 6, inverter 7 and adder 8, so that no multiplexer 3/4 and no second visit to
/// register 9 is needed: one result per clock. The arithmetic is the device's, function for
/// function (arith::pass with select 36 = 0, then 1; ROM 38, multiplier 39, 13–15), so the
/// results equal the patent's device on every operation, under every policy it takes.
///
/// Two Verilog tops share this model (the same bits, different registers):
/// \code{.unparsed}
///   one_pass            rtl/design_space/specular_one_pass.v: both passes and the tail in one clock;
///   one_pass_pipelined  rtl/design_space/specular_one_pass_pipelined.v: a register between the passes
///                       and before each multiplier of the tail.
/// \endcode
#pragma once

#include <string_view>

#include "specular/core.h"
#include "specular/variants/variant.h"

namespace specular {
namespace variants {

/// Variants "one_pass" and "one_pass_pipelined": the device's two passes in series on
/// two ROMs, one result per clock; the patent's device's bits.
class OnePass final : public Variant {
 public:
  /// Takes every policy of `config` (constants, normalisation, saturation); throws
  /// std::invalid_argument naming the width that is not the default (the only widths
  /// the Verilog tops are built for). `pipelined` only picks the name.
  OnePass(const Config& config, bool pipelined);
  std::string_view name() const override { return pipelined_ ? "one_pass_pipelined" : "one_pass"; }
  VariantResult run(const Operands& in) const override;

 private:
  Core core_;  ///< the tables (ROM 5, ROM 38) and pins 19/20 of this configuration
  bool pipelined_;
};

}  // namespace variants
}  // namespace specular
