#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "bench.h"

namespace specular_bench {

std::vector<Operands> random_operands(const specular::Core& core, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> cos_lambda(0.0, 1.0);
  std::uniform_int_distribution<long long> exponent(specular::n_min, specular::n_max);
  std::uniform_int_distribution<long long> intensity(0, 255);
  std::vector<Operands> ring;
  ring.reserve(ring_size);
  for (std::size_t i = 0; i < ring_size; ++i) {
    const double c = cos_lambda(rng);
    const long long n = exponent(rng);
    const long long r = intensity(rng), g = intensity(rng), b = intensity(rng);
    ring.push_back(core.operands(c, n, r, g, b));  // the user's path: checked, quantised
  }
  return ring;
}

Operands stream_operand(const std::vector<Operands>& ring, std::size_t i) {
  Operands op = ring[(i & ~(stream_block - 1)) % ring_size];
  op.cos = ring[i % ring_size].cos;
  return op;
}

void print_figure(const std::string& name, double value, const std::string& unit) {
  std::printf("%s: %.4g %s\n", name.c_str(), value, unit.c_str());
  std::fflush(stdout);
}

void print_checksum(const std::string& name, std::uint64_t value) {
  std::printf("%s: %016" PRIx64 " hex\n", name.c_str(), value);
  std::fflush(stdout);
}

long peak_memory_kb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) {
      std::istringstream fields(line.substr(6));
      long kb = 0;
      fields >> kb;
      return kb;
    }
  }
  return -1;  // not Linux: the figure prints as -1 kB rather than a made-up number
}

double now_seconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

}  // namespace specular_bench
