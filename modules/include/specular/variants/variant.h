/// \file
/// Design variants (issue 26, docs/design_space.md): other ways to compute the device's
/// K(n)·cos^n λ·{R, G, B}, each a bit-accurate model of its own Verilog top in rtl/,
/// side by side with the patent's device.
///
/// Every variant takes the device's operands (register 1's cos code, n, R, G, B at the
/// default widths) and returns two things in the device's own formats, so that errors,
/// outputs and silicon compare like for like:
///   - lobe: K(n)·cos^n λ as multiplier 39's output (Formats::norm, S10.20 by default),
///   - out: pins 24–26 (Formats::out, S18.13), lobe × R, G, B as multipliers 13–15 do.
/// Each variant reuses arith.h's block functions where its arithmetic is the device's
/// (ROM 5's log2, ROM 38's K(n), multipliers 39 and 13–15): a block's arithmetic lives once.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "specular/core.h"

namespace specular {
/// Design variants: bit-accurate models of other ways to compute the lobe (see variant.h).
namespace variants {

/// One operation's result: the lobe and pins 24–26 (see variant.h).
struct VariantResult {
  code_t lobe = 0;              ///< K(n)·cos^n λ, multiplier 39's format (S10.20)
  std::array<code_t, 3> out{};  ///< pins 24–26: lobe × R, G, B (S18.13)
};

/// A bit-accurate model of one design variant's Verilog top.
class Variant {
 public:
  virtual ~Variant() = default;
  /// The registry's name (`specular_tb --variant NAME`, the Verilog top specular_NAME).
  virtual std::string_view name() const = 0;
  /// One operation on operands from Core::operands() (codes on their buses).
  virtual VariantResult run(const Operands& in) const = 0;
};

/// Every registered variant's name, the patent's device ("patent") first.
std::vector<std::string> variant_names();

/// A variant built for `config`. Throws std::invalid_argument naming an unknown name
/// and the known ones, or a configuration the variant is not built for (every variant
/// takes the default widths; which policies each takes is in docs/design_space.md).
std::unique_ptr<Variant> make_variant(std::string_view name, const Config& config = Config{});

/// The patent's device as a variant: Core's two passes, lobe = multiplier 39's output.
class PatentDevice final : public Variant {
 public:
  /// A Core for `config`; throws as Core's constructor does.
  explicit PatentDevice(const Config& config) : core_(config) {}
  std::string_view name() const override { return "patent"; }
  VariantResult run(const Operands& in) const override {
    const Result r = core_.run(in);
    return VariantResult{r.norm39, r.out};
  }

 private:
  Core core_;
};

}  // namespace variants
}  // namespace specular
