// soc_platform: the specular IP in a small SoC (platform.h) — a processor-like
// initiator with a quantum keeper, a generic bus, a RAM — run with the chosen target.
//
//   soc_platform [--target lt|pin|rtl|rtl-sync|axi] [--operations N] [--strict]
//                [--pin-delay keep|consume]
//
// --strict: the CPU asserts, as riscv-vp's memory interface does, that b_transport
// never returns a delay smaller than the local time it passed in (platform.h).
// --pin-delay: the pin target's delay policy (PinTargetSettings::delay; default keep,
// docs/integration.md §6); consume under --strict aborts at the first START.
// Prints one line and exits 0 when every result equals Core's and every operation
// raised one interrupt; 1 otherwise; 2 for a bad command line; a strict assert that
// fails aborts. A second line gives the IP's energy over the run (issue 61,
// docs/energy.md): what a power-aware platform reads from SpecularTarget::energy().
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

#include "platform.h"

namespace {

int usage(const std::string& problem) {
  std::cerr << "soc_platform: " << problem << "\n"
            << "usage: soc_platform [--target lt|pin|rtl|rtl-sync|axi] [--operations N] [--strict]"
               " [--pin-delay keep|consume]  (N in 1.."
            << soc::max_operations << ")\n";
  return 2;
}

}  // namespace

int sc_main(int argc, char* argv[]) {
  soc::Target target = soc::Target::lt;
  std::string target_name = "lt";
  long operations = 50;
  bool strict = false;
  specular::PinDelay pin_delay = specular::PinTargetSettings{}.delay;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--target" || arg == "--operations" || arg == "--pin-delay") && i + 1 == argc)
      return usage(arg + " needs a value");
    if (arg == "--target") {
      target_name = argv[++i];
      if (target_name == "lt") target = soc::Target::lt;
      else if (target_name == "pin") target = soc::Target::pin;
      else if (target_name == "rtl") target = soc::Target::rtl;
      else if (target_name == "rtl-sync") target = soc::Target::rtl_sync;
      else if (target_name == "axi") target = soc::Target::axi;
      else return usage("unknown target '" + target_name + "' (allowed: lt, pin, rtl, rtl-sync, axi)");
    } else if (arg == "--operations") {
      const std::string value = argv[++i];
      char* end = nullptr;
      operations = std::strtol(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || operations < 1 ||
          operations > static_cast<long>(soc::max_operations))
        return usage("--operations '" + value + "' is not a whole number in 1.." +
                     std::to_string(soc::max_operations));
    } else if (arg == "--strict") {
      strict = true;
    } else if (arg == "--pin-delay") {
      try {
        pin_delay = specular::pin_delay_from_string(argv[++i]);
      } catch (const std::invalid_argument& e) {
        return usage(std::string("--pin-delay: ") + e.what());
      }
    } else {
      return usage("unknown argument '" + arg + "'");
    }
  }
  if (!soc::Platform::has(target))
    return usage("this build has no " + target_name +
                 " target (the package was installed or found without its rtl component)");

  soc::Platform platform("soc", target, static_cast<std::size_t>(operations), strict, pin_delay);
  sc_core::sc_start();

  const soc::Cpu& cpu = platform.cpu;
  const bool pass = cpu.failure.empty() && cpu.operations_done == static_cast<std::size_t>(operations) &&
                    cpu.matches == cpu.operations_done && platform.interrupts == cpu.operations_done;
  std::cout << "soc_platform: target " << target_name << (strict ? " (strict initiator)" : "")
            << ": " << cpu.matches << "/" << operations
            << " operations equal to Core, " << platform.interrupts << " interrupts, "
            << sc_core::sc_time_stamp() << " simulated"
            << (target == soc::Target::pin ? std::string(", pin delay ") + specular::to_string(pin_delay) : "")
            << (cpu.failure.empty() ? "" : ", failure: " + cpu.failure) << ": "
            << (pass ? "PASS" : "FAIL") << std::endl;
  // What the IP's work cost, as its gate-level figures price it (docs/energy.md).
  const specular::energy::EnergyTally e = platform.ip->energy();
  const double ops = static_cast<double>(e.operations > 0 ? e.operations : 1);
  const double ns = sc_core::sc_time_stamp().to_seconds() * 1e9;
  std::cout << "soc_platform: energy " << e.total_pj() / 1000 << " nJ, " << e.total_pj() / ops
            << " pJ per operation (operations " << e.operation_pj / ops << ", register reads "
            << e.read_pj / ops << ", writes " << e.write_pj / ops << ", clocks " << e.clock_pj / ops
            << "; the " << (platform.ip->energy_calibration() == specular::energy::Calibration::drawn_device
                                ? "drawn"
                                : "synchronous")
            << " device's figures), mean power " << (ns > 0 ? e.total_pj() / ns : 0.0) << " mW" << std::endl;
  return pass ? 0 : 1;
}
