/// \file
/// Design variant us5739820_pipelined (docs/variants/us5739820.md): us5739820's
/// arithmetic unrolled into ten squarer stages, one start a clock
/// (rtl/design_space/specular_us5739820_pipelined.v). Every stage squares or passes y on, so the bits
/// are us5739820's: this model is that one under its own name.
#pragma once

#include <string_view>

#include "specular/variants/us5739820.h"

namespace specular {
namespace variants {

/// Variant "us5739820_pipelined": Us5739820's bits from ten squarer stages, one start a clock.
class Us5739820Pipelined final : public Variant {
 public:
  /// Takes and refuses what Us5739820 does (the same std::invalid_argument).
  explicit Us5739820Pipelined(const Config& config) : sequential_(config) {}
  std::string_view name() const override { return "us5739820_pipelined"; }
  VariantResult run(const Operands& in) const override { return sequential_.run(in); }

 private:
  Us5739820 sequential_;
};

}  // namespace variants
}  // namespace specular
