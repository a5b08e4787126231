// The main thread's stack, told to AddressSanitizer where SystemC 2.3.4 leaves it out
// (issue 45; docs/testing/sanitizers.md, "Sanitizers and SystemC's coroutines").
//
// Why: SystemC 2.3.4 tells ASan of its QuickThreads stack switches through the weak
// __sanitizer_start_switch_fiber / __sanitizer_finish_switch_fiber, but
//   - a switch back to the main coroutine gives ASan no stack (SystemC does not know the
//     main stack: it passes 0 and size 0), and
//   - a finished SC_THREAD leaves its stack by QuickThreads' abort, which tells ASan
//     nothing: ASan keeps the dead coroutine's stack as the thread's stack.
// After sc_start returns, ASan may so hold an unmapped or guard-protected coroutine stack
// as the main thread's. LeakSanitizer scans that range at exit and its tracer faults on
// a protected page ("Tracer caught signal 11 ... LeakSanitizer has encountered a fatal
// error"), where the memory happens to be laid out so (always under `setarch -R` on the
// machine that reported it).
//
// What this does:
//   1. Before main, while ASan still holds the real main stack, it reads that stack's
//      bounds (the same start/finish pair, used as a query) and registers an atexit
//      handler. atexit handlers run in reverse order, and ASan registered its leak check
//      at its own initialisation, before any constructor: so the handler runs first, on
//      the main stack, and hands ASan the main stack back. LeakSanitizer then scans from
//      the stack pointer to the top of the real main stack, as in a program without
//      coroutines.
//   2. With gcc (shared libasan), SystemC's switch to its main coroutine is given the main
//      stack instead of (0, 0), through a definition of __sanitizer_start_switch_fiber
//      that libsystemc's weak reference binds to (below).
//
// Compiled once, in a sanitizer build only, and linked into every executable and shared
// library that links SystemC (CMakeLists.txt: SPECULAR_SANITIZE, SPECULAR_FUZZ). Without ASan, dlsym finds nothing and this does
// nothing. SPECULAR_ASAN_KEEP_SYSTEMC_STACK=1 turns it off, to see the fault it prevents.
#include <dlfcn.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#define SANITIZER_START_SWITCH "__sanitizer_start_switch_fiber"
#define SANITIZER_FINISH_SWITCH "__sanitizer_finish_switch_fiber"

namespace {

using StartSwitch = void (*)(void**, const void*, std::size_t);
using FinishSwitch = void (*)(void*, const void**, std::size_t*);

// ASan's own functions (null without ASan).
StartSwitch asan_start_switch = nullptr;
FinishSwitch asan_finish_switch = nullptr;

/// The sanitizer runtime's `name`: after this executable's own definitions where the
/// runtime is a shared library (gcc), in the executable where clang linked it in.
template <class Function>
Function asan_function(const char* name) {
#if defined(__clang__)
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
#else
  return reinterpret_cast<Function>(dlsym(RTLD_NEXT, name));
#endif
}

const void* main_stack_bottom = nullptr;
std::size_t main_stack_size = 0;

/// At exit, before the leak check: the real main stack back, if we are on it. exit()
/// called on a coroutine's stack (inside an SC_THREAD) keeps the stack SystemC last
/// announced, which is then the right one.
void give_back_main_stack() {
  const auto here = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
  const auto bottom = reinterpret_cast<std::uintptr_t>(main_stack_bottom);
  if (bottom == 0 || here < bottom || here >= bottom + main_stack_size) return;
  void* fake_stack = nullptr;  // the current one, kept
  asan_start_switch(&fake_stack, main_stack_bottom, main_stack_size);
  asan_finish_switch(fake_stack, nullptr, nullptr);
}

/// Before main: the bounds ASan gave the main thread at start-up, read by switching to an
/// empty stack (finish returns the stack left) and straight back.
__attribute__((constructor)) void remember_main_stack() {
  asan_start_switch = asan_function<StartSwitch>(SANITIZER_START_SWITCH);
  asan_finish_switch = asan_function<FinishSwitch>(SANITIZER_FINISH_SWITCH);
  if (asan_start_switch == nullptr || asan_finish_switch == nullptr) return;
  const char* keep = std::getenv("SPECULAR_ASAN_KEEP_SYSTEMC_STACK");
  if (keep != nullptr && std::strcmp(keep, "1") == 0) return;  // off: SystemC's calls unchanged
  void* main_fake_stack = nullptr;
  asan_start_switch(&main_fake_stack, nullptr, 0);
  asan_finish_switch(nullptr, &main_stack_bottom, &main_stack_size);
  asan_start_switch(nullptr, main_stack_bottom, main_stack_size);
  asan_finish_switch(main_fake_stack, nullptr, nullptr);
  std::atexit(give_back_main_stack);
}

}  // namespace

// SystemC 2.3.4's switch to its main coroutine names no stack (0, 0): the main stack is
// named instead, so that ASan knows where the scheduler and every SC_METHOD run (an
// exception thrown there, an sc_report, otherwise finds no stack: "ASan is ignoring
// requested __asan_handle_no_return ... top: 0x000000000000"). libsystemc's weak reference
// binds to this definition, the executable's, before the sanitizer runtime's. Only where
// that runtime is a shared library (gcc's libasan): clang links its runtime into the
// executable, where a second definition cannot be.
#if !defined(__clang__)
extern "C" void __sanitizer_start_switch_fiber(void** fake_stack_save, const void* bottom,
                                               std::size_t size) {
  static const StartSwitch asan = asan_function<StartSwitch>(SANITIZER_START_SWITCH);
  if (bottom == nullptr && size == 0 && main_stack_size != 0) {  // 0 when switched off
    bottom = main_stack_bottom;
    size = main_stack_size;
  }
  if (asan != nullptr) asan(fake_stack_save, bottom, size);
}
#endif
