// A design variant's verilated top (rtl/design_space/specular_NAME.v) equals its C++ model
// (specular::variants::make_variant(NAME)) to the bit: the lobe and pins 24–26 of every
// operation, streamed through the variants' common ports (twin/variants/variant_rtl.h).
// Built once per variant by tests/CMakeLists.txt: VARIANT_NAME, VARIANT_HEADER and
// VARIANT_TOP name it; VARIANT_EXHAUSTIVE builds the long test (every cos code × every n,
// split by SPECULAR_OPERATION_SHARD), otherwise the quick slice (every n, 259 cos codes).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include VARIANT_HEADER
#include "operation_shard.h"
#include "specular/variants/variant.h"
#include "variant_rtl.h"

namespace {

using specular::Operands;
using specular::code_t;
using specular::variants::VariantResult;

constexpr unsigned n_max = 1000;
constexpr code_t cos_one = code_t{1} << 16;

/// Intensities that walk 0..255 across the sweep, different on each channel.
Operands operands(code_t cos, unsigned n) {
  Operands in;
  in.cos = cos;
  in.n = n;
  in.rgb = {static_cast<code_t>((cos + 3 * n) & 255), static_cast<code_t>((5 * cos + n) & 255),
            static_cast<code_t>(255 - ((cos + n) & 255))};
  return in;
}

/// The cos codes a run covers: every one, or 0, 1, 2, every 256th and the last three.
std::vector<code_t> cos_codes(bool every) {
  std::vector<code_t> codes;
  for (code_t c = 0; c <= cos_one; ++c)
    if (every || c <= 2 || c % 256 == 0 || c >= cos_one - 2) codes.push_back(c);
  return codes;
}

struct Mismatch {
  std::size_t count = 0;
  std::string first;
};

void expect_rtl_equals_model(bool every) {
  // The whole run splits its n across shards (SPECULAR_OPERATION_SHARD or GoogleTest's);
  // the quick slice takes every n in every shard.
  const auto shard = every ? specular::testing_support::operation_shard()
                           : specular::testing_support::OperationShard{};
  const auto model = specular::variants::make_variant(VARIANT_NAME);
  const std::vector<code_t> codes = cos_codes(every);
  std::vector<unsigned> ns;
  for (unsigned n = 1; n <= n_max; ++n)
    if (!every || shard.covers(n)) ns.push_back(n);
  const std::size_t count = codes.size() * ns.size();
  const auto op = [&](std::size_t i) { return operands(codes[i % codes.size()], ns[i / codes.size()]); };

  specular::variants::VariantRtl<VARIANT_TOP> rtl;
  Mismatch mismatch;
  rtl.stream(count, op, [&](std::size_t i, const VariantResult& got) {
    const Operands in = op(i);
    const VariantResult want = model->run(in);
    if (got.lobe == want.lobe && got.out == want.out) return;
    if (mismatch.count++ == 0)
      mismatch.first = "cos code " + std::to_string(in.cos) + ", n " + std::to_string(in.n) +
                       ": lobe " + std::to_string(got.lobe) + " (model " + std::to_string(want.lobe) +
                       "), R " + std::to_string(got.out[0]) + " (model " + std::to_string(want.out[0]) + ")";
  });
  EXPECT_EQ(mismatch.count, 0u) << VARIANT_NAME << ": " << mismatch.count << " of " << count
                                << " operations differ; first: " << mismatch.first;
  ::testing::Test::RecordProperty("operations", std::to_string(count));
  ::testing::Test::RecordProperty("clocks_per_result", std::to_string(static_cast<double>(rtl.clocks()) / count));
}

}  // namespace

#ifdef VARIANT_EXHAUSTIVE
SPECULAR_OPERATION_SHARDED_SUITE(VariantRtl);
TEST(VariantRtl, EveryCosCodeAndEveryNEqualsTheModel) { expect_rtl_equals_model(true); }
#else
TEST(VariantRtl, EveryNOnACosSliceEqualsTheModel) { expect_rtl_equals_model(false); }
#endif
