// A SystemC program with one leak planted in our own code, and one allocation that only
// the main thread's stack holds when exit() runs. scripts/verify/sanitizer_exit_check.sh runs it
// under the sanitizer settings and `setarch -R` and asks LeakSanitizer's report for:
//   - the planted leak, allocated on an SC_THREAD's coroutine stack: reported, so leak
//     detection still sees our code's leaks (issue 45);
//   - the held allocation: not reported, so the main thread's real stack is scanned at
//     exit (with a coroutine's stack in its place, it is reported as a leak);
//   - no LeakSanitizer fatal error.
// Built in sanitizer builds only (tests/CMakeLists.txt); not a GoogleTest program.
#include <cstdio>
#include <cstdlib>

#include "specular/systemc.h"

namespace {

/// Allocates and drops the pointer: the leak LeakSanitizer must report, named by this frame.
__attribute__((noinline)) void specular_planted_leak_on_coroutine() {
  int* volatile lost = new int[16];
  lost[0] = 1;
}

/// Allocates what sc_main keeps on its own stack frame until exit(): never a leak.
__attribute__((noinline)) int* specular_held_on_main_stack() { return new int[32]; }

SC_MODULE(PlantedLeak) {
  void run() {
    wait(1, sc_core::SC_NS);
    specular_planted_leak_on_coroutine();
    wait(1, sc_core::SC_NS);
  }
  SC_CTOR(PlantedLeak) { SC_THREAD(run); }
};

}  // namespace

int sc_main(int, char*[]) {
  int* volatile held = specular_held_on_main_stack();
  held[0] = 2;
  PlantedLeak planted("planted");
  sc_core::sc_start(10, sc_core::SC_NS);
  std::printf("planted_leak: simulated to %s, exiting with the held block live\n",
              sc_core::sc_time_stamp().to_string().c_str());
  std::fflush(stdout);
  std::exit(held[0] == 2 ? 0 : 1);  // the leak check runs here, sc_main's frame still live
}
