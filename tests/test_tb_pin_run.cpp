// The model dispatch on the pin model, in process (one elaboration): results within
// tolerance of the double reference, measured latency 2.5 periods, and the same
// codes as the core model through the same entry point.
#include <gtest/gtest.h>

#include <cmath>

#include "run_models.h"
#include "specular/core.h"
#include "specular/reference.h"

using namespace specular;
using namespace specular::tb;

TEST(TbPinRun, BatchesAgainstReferenceAndCore) {
  RunSettings settings;
  settings.model = Model::pin;
  settings.clock_period_ps = 8000;
  settings.chunk_size = 3;  // several batches, some with n changing inside
  const Core core(settings.config);
  std::vector<Operands> ops;
  for (const auto& [cos, n, r, g, b] :
       std::vector<std::tuple<double, int, int, int, int>>{{0.0, 1, 255, 255, 255},
                                                           {1.0, 1, 255, 255, 255},
                                                           {0.5, 1, 255, 255, 255},
                                                           {0.9, 10, 200, 100, 50},
                                                           {0.95, 10, 200, 100, 50},
                                                           {1 - 1.0 / 65536, 1000, 1, 2, 3},
                                                           {0.999, 1000, 1, 2, 3},
                                                           {0.25, 2, 0, 0, 0}})
    ops.push_back(core.operands(cos, n, r, g, b));

  std::vector<Result> pin, again;
  std::vector<double> cycles, core_cycles;
  run_operations(settings, ops, pin, cycles);
  ASSERT_EQ(pin.size(), ops.size());
  ASSERT_EQ(cycles.size(), ops.size());

  const Formats& f = core.formats();
  for (std::size_t i = 0; i < ops.size(); ++i) {
    SCOPED_TRACE(i);
    const double cos_q = std::ldexp(static_cast<double>(ops[i].cos), -16);
    const unsigned n = static_cast<unsigned>(ops[i].n);
    const double k = 2 * M_PI / (n + 2);  // patent policy
    const double log2_cos = ops[i].cos == 0 ? -16.0 : std::log2(cos_q);
    const double a = std::max(0.0, 1 - 0.5 * std::log2(1 - n * log2_cos));
    EXPECT_EQ(pin[i].reg1, ops[i].cos);
    EXPECT_NEAR(f.reg9.to_real(pin[i].reg9_pass1), 1 - n * log2_cos, 1e-3 * n);
    EXPECT_NEAR(f.reg9.to_real(pin[i].reg9_pass2), a, reference::approx_tolerance());
    EXPECT_NEAR(f.norm.to_real(pin[i].norm39), k * a, reference::norm_tolerance(k));
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(f.out.to_real(pin[i].out[ch]), k * a * ops[i].rgb[ch],
                  reference::out_tolerance(k, double(ops[i].rgb[ch]), f.out.lsb()));
    EXPECT_EQ(cycles[i], 2.5) << "spec timing table: start to 35 rising";
  }

  settings.model = Model::core;
  run_operations(settings, ops, again, core_cycles);
  ASSERT_EQ(again.size(), ops.size());
  for (std::size_t i = 0; i < ops.size(); ++i) {
    EXPECT_EQ(pin[i].reg1, again[i].reg1);
    EXPECT_EQ(pin[i].reg9_pass1, again[i].reg9_pass1);
    EXPECT_EQ(pin[i].reg9_pass2, again[i].reg9_pass2);
    EXPECT_EQ(pin[i].norm39, again[i].norm39);
    EXPECT_EQ(pin[i].out, again[i].out);
    EXPECT_EQ(core_cycles[i], spec_latency_cycles);
  }
}
