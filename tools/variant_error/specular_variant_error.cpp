// specular_variant_error: a design variant's exhaustive error (variant_error.h).
// It links the IP library, hence SystemC, whose library defines a main that calls
// sc_main: the tool's entry is sc_main, as specular_tb's and specular_prove's are (a
// plain main left sc_main undefined where the linker kept libsystemc, the sanitizer build).
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "specular/systemc.h"
#include "variant_error.h"

int sc_main(int argc, char** argv) {
  return specular::tb::run_variant_error(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}
