// main() for every test executable: GoogleTest runs inside sc_main, as VCML does,
// so that a test may elaborate a design and call sc_start (once per process).
#include <gtest/gtest.h>

#include <cstdlib>
#include <systemc>

int sc_main(int, char**) { return RUN_ALL_TESTS(); }

int main(int argc, char** argv) {
  // The banner would mix into --gtest_list_tests, which ctest parses.
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  testing::InitGoogleTest(&argc, argv);
  return sc_core::sc_elab_and_sim(argc, argv);
}
