// specular_soak: see soak.h and --help. Each SystemC stage runs in a child process,
// because SystemC elaborates once per process and a pin model's clock would keep
// ticking under the next stage.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.h"
#include "soak.h"
#include "specular/systemc.h"

namespace {

using specular::soak::StageFigures;

/// Runs `stage` in a child process; its figures line goes to standard output.
/// Returns true when the child exited 0 (no mismatch).
bool in_child(const std::function<StageFigures()>& stage) {
  std::cout.flush();
  const pid_t child = fork();
  if (child < 0) {
    std::perror("specular_soak: fork");
    return false;
  }
  if (child == 0) {
    // sc_stop's "Simulation stopped by user" would interleave with the figures.
    sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
    int status = 3;
    try {
      const StageFigures figures = stage();
      std::cout << specular::soak::format_figures(figures) << std::endl;
      status = figures.mismatches == 0 ? 0 : 1;
    } catch (const std::exception& e) {
      std::cerr << "specular_soak: " << e.what() << std::endl;
    }
    std::_Exit(status);  // no SystemC teardown in the child
  }
  int status = 0;
  if (waitpid(child, &status, 0) != child) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int soak(const specular::soak::SoakOptions& options) {
  std::cout << "specular_soak: seed " << options.seed << "; core " << options.core_ops << ", pin "
            << options.pin_ops << ", tlm " << options.tlm_ops << ", tlm-pin " << options.tlm_pin_ops
            << " operations; constants " << specular::to_string(options.constants) << std::endl;
  bool pass = true;
  if (options.core_ops > 0) {
    std::vector<std::string> skipped;
    const StageFigures core = specular::soak::run_core_stage(options, &skipped);
    for (const std::string& policy : skipped)
      std::cout << "specular_soak: core: " << policy << " skipped (the device refuses it under constants "
                << specular::to_string(options.constants) << ")" << std::endl;
    std::cout << specular::soak::format_figures(core) << std::endl;
    pass = pass && core.mismatches == 0;
  }
  if (options.pin_ops > 0)
    pass = in_child([&] { return specular::soak::run_pin_stage(options); }) && pass;
  if (options.tlm_ops > 0)
    pass = in_child([&] { return specular::soak::run_tlm_stage(options, false); }) && pass;
  if (options.tlm_pin_ops > 0)
    pass = in_child([&] { return specular::soak::run_tlm_stage(options, true); }) && pass;
  std::cout << "specular_soak: " << (pass ? "PASS (no mismatch)" : "FAIL") << std::endl;
  return pass ? 0 : 1;
}

}  // namespace

int sc_main(int argc, char** argv) {
  specular::cli::Command app{specular::soak::soak_description, "specular_soak"};
  specular::cli::house_rules(app, specular::soak::soak_footer);
  specular::soak::SoakOptions options;
  specular::soak::add_soak_options(app, options);
  return specular::cli::run(app, argc, argv, [&] { return soak(options); });
}

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}
