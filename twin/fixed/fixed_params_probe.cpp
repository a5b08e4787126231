// Run once at configure time (twin/fixed/rtl_sync_fixed.cmake, try_run): prints the
// Verilog parameters that fix specular_device_sync to one configuration at the default
// widths — pin 19's and pin 20's codes (constants.cpp, the one place they are written),
// the ROM 38 bank and adder 8's policy — as `-G` arguments of Verilator, one per line.
// The configuration comes as PROBE_CONSTANTS, PROBE_NORMALISATION, PROBE_SATURATION
// (policy names as specular_tb takes them) in probe_config.h, written beside the probe.
#include <cstdio>
#include <exception>

// The library's own definitions, compiled into this one probe: no library exists yet
// when CMake configures.
#include "../../modules/src/constants.cpp"
#include "../../modules/src/format.cpp"
#include "specular/core.h"
#include "specular/rom38_banks.h"
#include "probe_config.h"

int main() {
  try {
    using namespace specular;
    Config config;
    config.constants = parse_constants(PROBE_CONSTANTS);
    config.normalisation = parse_normalisation(PROBE_NORMALISATION);
    config.saturation = parse_saturation(PROBE_SATURATION);
    const Formats formats(config.widths);
    const code_t h = pin19_code(formats, config.constants);
    const code_t a = pin20_code(formats, config.constants);
    if (h < 0 || a < 0) throw std::invalid_argument("pins 19 and 20 carry non-negative constants");
    std::printf("-GFIXED_CONFIG=1\n");
    std::printf("-GFIXED_H19=%d'd%lld\n", formats.mux4.width(),
                static_cast<long long>(h));
    std::printf("-GFIXED_A20=%d'd%lld\n", formats.reg9.width(),
                static_cast<long long>(a));
    std::printf("-GFIXED_CARRY34=1\n");
    std::printf("-GFIXED_LITERAL=%d\n", config.saturation == Saturation::literal ? 1 : 0);
    std::printf("-GFIXED_ROM38_BANK=%u\n", rom38_bank(config));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
