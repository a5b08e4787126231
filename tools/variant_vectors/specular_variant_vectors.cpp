// specular_variant_vectors: the vector file of rtl/tb/specular_variant_tb.v for one
// design variant (docs/design_space/flow.md, "Silicon flow for variants"): one operation per
// line, in hex, `cos n r g b lobe out_r out_g out_b`, the expected lobe (S10.20, 31 bits)
// and pins 24-26 (S18.13, 32 bits) computed by the variant's C++ model (make_variant),
// which its Verilog top equals to the bit (test_variant_rtl_NAME).
//
//   specular_variant_vectors NAME [--count N] [--seed S] [--out FILE]
//
// The edge cases first (cos 0 and 1, n 1 and 1000, R, G, B 0 and 255, the smallest
// non-zero cos code), then random operands from std::mt19937_64(seed) up to N operations
// (default 200, seed 1): n 1..1000, R, G, B 0..255, and cos uniform on 0..65536 for one
// operation in four, else the code nearest p^(1/n) for p uniform on (0, 1) (a uniform cos
// makes cos^n underflow to 0 for most n: these keep the lobe spread over its range).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.h"
#include "specular/variants/variant.h"
#include "usage_error.h"

namespace {

using specular::Operands;
using specular::code_t;

constexpr code_t cos_one = code_t{1} << 16;

Operands make(code_t cos, code_t n, code_t r, code_t g, code_t b) {
  Operands in;
  in.cos = cos;
  in.n = n;
  in.rgb = {r, g, b};
  return in;
}

std::vector<Operands> edge_cases() {
  std::vector<Operands> v;
  for (code_t cos : {code_t{0}, cos_one, code_t{1}, cos_one - 1, cos_one / 2})
    for (code_t n : {code_t{1}, code_t{1000}, code_t{2}})
      v.push_back(make(cos, n, 255, 0, 128));
  v.push_back(make(cos_one, 1, 255, 255, 255));
  v.push_back(make(cos_one, 1000, 255, 255, 255));
  v.push_back(make(0, 1, 0, 0, 0));
  return v;
}

unsigned long long bits(code_t value, int width) {
  return static_cast<unsigned long long>(value) & ((1ULL << width) - 1);
}

}  // namespace

int main(int argc, char** argv) {
  specular::cli::Command app{"The vector file of rtl/tb/specular_variant_tb.v for one design variant: one operation per\n"
                             "line, in hex, cos n r g b lobe out_r out_g out_b, the expected values from the variant's\n"
                             "C++ model; the edge cases first, then random operands.",
                             "specular_variant_vectors"};
  specular::cli::house_rules(app, "Exit status: 0 written, 1 the output failed, 2 bad usage.");
  std::string name, out_path;
  long long count = 200;
  std::uint64_t seed = 1;
  app.add_option("NAME", name, "the variant (specular_variant_error --list)")
      ->required()
      ->check(specular::cli::parsed_by([](const std::string& v) { specular::variants::make_variant(v); }));
  app.add_option("--count", count, "operations in all")
      ->type_name("N")
      ->capture_default_str()
      ->check(specular::cli::integer_in(1, 8192));
  app.add_option("--seed", seed, "std::mt19937_64's seed")
      ->type_name("S")
      ->capture_default_str()
      ->check(specular::cli::unsigned64());
  app.add_option("--out", out_path, "write there (default: standard output)")->type_name("FILE");
  return specular::cli::run(app, argc, argv, [&] {
    const auto variant = specular::variants::make_variant(name);
    std::vector<Operands> ops = edge_cases();
    if (static_cast<long long>(ops.size()) > count) ops.resize(static_cast<std::size_t>(count));
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<code_t> cos_d(0, cos_one), n_d(1, 1000), i_d(0, 255), kind_d(0, 3);
    std::uniform_real_distribution<double> p_d(0.0, 1.0);
    while (static_cast<long long>(ops.size()) < count) {
      const code_t n = n_d(rng);
      const code_t cos = kind_d(rng) == 0
          ? cos_d(rng)
          : static_cast<code_t>(std::lround(std::pow(p_d(rng), 1.0 / static_cast<double>(n)) *
                                            static_cast<double>(cos_one)));
      const code_t r = i_d(rng), g = i_d(rng), b = i_d(rng);
      ops.push_back(make(cos, n, r, g, b));
    }
    std::ofstream file;
    if (!out_path.empty()) {
      file.open(out_path);
      if (!file) throw specular::tb::UsageError("cannot write '" + out_path + "'");
    }
    std::ostream& out = out_path.empty() ? std::cout : file;
    char line[160];
    for (const Operands& in : ops) {
      const auto res = variant->run(in);
      std::snprintf(line, sizeof line, "%05llx %03llx %02llx %02llx %02llx %08llx %08llx %08llx %08llx\n",
                    bits(in.cos, 17), bits(in.n, 10), bits(in.rgb[0], 8), bits(in.rgb[1], 8),
                    bits(in.rgb[2], 8), bits(res.lobe, 31), bits(res.out[0], 32), bits(res.out[1], 32),
                    bits(res.out[2], 32));
      out << line;
    }
    return out ? 0 : 1;
  });
}
