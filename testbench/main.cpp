// specular_tb: the main testbench (see testbench.h; --help for the options).
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "specular/systemc.h"
#include "testbench.h"

int sc_main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  return specular::tb::run_testbench(args, std::cout, std::cerr);
}

int main(int argc, char** argv) {
  // SystemC's banner would land in the middle of a CSV or JSON report on stdout.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}
