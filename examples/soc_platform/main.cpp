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
// The options through CLI11 (libcli11-dev; --help, --version). Prints one line and exits
// 0 when every result equals Core's and every operation raised one interrupt; 1
// otherwise; 2 for a bad command line; a strict assert that fails aborts. A second line gives the IP's energy over the run (issue 61,
// docs/energy.md): what a power-aware platform reads from SpecularTarget::energy().
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

#include "platform.h"

namespace {

/// A whole number in [1, max_operations], typed in decimal: CLI11 reads "010" as octal,
/// so the text is checked here and handed on as plain decimal.
std::string check_operations(std::string& text) {
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < 1 || value > static_cast<long>(soc::max_operations))
    return "'" + text + "' is not a whole number in 1.." + std::to_string(soc::max_operations);
  text = std::to_string(value);
  return {};
}

}  // namespace

int sc_main(int argc, char* argv[]) {
  // The options are declared once, with CLI11 (as the project's tools: docs/misuse.md):
  // --help comes from the declarations; a bad value is one line naming it and the
  // allowed values, exit status 2.
  CLI::App app{"The specular IP in a small SoC: a CPU with a quantum keeper, a bus, a RAM and the IP "
               "behind the chosen target. Exit 0 when every result equals Core's and every operation "
               "raised one interrupt, 1 otherwise, 2 for a bad command line.",
               "soc_platform"};
  app.set_version_flag("--version", std::string("soc_platform ") + SPECULAR_EXAMPLE_VERSION,
                       "print the version and exit");
  std::string target_name = "lt";
  long operations = 50;
  bool strict = false;
  specular::PinDelay pin_delay = specular::PinTargetSettings{}.delay;
  app.add_option("--target", target_name, "the IP's target: lt, pin, rtl, rtl-sync or axi (default lt)")
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {
            for (const char* allowed : {"lt", "pin", "rtl", "rtl-sync", "axi"})
              if (name == allowed) return {};
            return "unknown target '" + name + "' (allowed: lt, pin, rtl, rtl-sync, axi)";
          },
          "TARGET"));
  app.add_option("--operations", operations, "operations the CPU runs, 1.." + std::to_string(soc::max_operations) +
                                                 " (default 50)")
      ->check(CLI::Validator(check_operations, "N"));
  app.add_flag("--strict", strict,
               "the CPU asserts, as riscv-vp's memory interface does, that b_transport never returns a "
               "delay smaller than the local time it passed in");
  app.add_option_function<std::string>(
      "--pin-delay", [&](const std::string& name) { pin_delay = specular::pin_delay_from_string(name); },
      "the pin target's delay policy: keep or consume (default keep; docs/integration.md)")
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {
            try {
              specular::pin_delay_from_string(name);
              return {};
            } catch (const std::invalid_argument& e) {
              return e.what();
            }
          },
          "keep|consume"));
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::cerr << "soc_platform: error: " << e.what() << "\n";
    return 2;
  }
  soc::Target target = soc::Target::lt;
  if (target_name == "pin") target = soc::Target::pin;
  else if (target_name == "rtl") target = soc::Target::rtl;
  else if (target_name == "rtl-sync") target = soc::Target::rtl_sync;
  else if (target_name == "axi") target = soc::Target::axi;
  if (!soc::Platform::has(target)) {
    std::cerr << "soc_platform: error: --target: this build has no " << target_name
              << " target (the package was installed or found without its rtl component)\n";
    return 2;
  }

  soc::Platform platform("soc", target, static_cast<std::size_t>(operations), strict, pin_delay);
  platform.ip->set_energy_model(true);  // the second line reports it (issue 61)
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
