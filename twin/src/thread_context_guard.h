// Verilator 5.006 keeps a per-thread "current context" (Verilated::threadContextp): a
// model's scopes unregister from it when the model is destroyed (VerilatedScope's
// destructor), and a new trace writer reads its time unit from it. Our models own their
// contexts, so a model being destroyed makes its own context current (so its scopes
// unregister there), and afterwards the thread must not be left pointing at that
// destroyed context: a writer opened next (RtlDeviceBase::allow_tracing swaps a
// specialised model for the traced one, then opens the file) read freed memory
// (AddressSanitizer, heap-use-after-free in VerilatedContext::timeunit).
#pragma once

#include <verilated.h>

namespace specular {

/// Declared after a model's VerilatedContext and before the model it holds: destroyed
/// between them, it hands the thread Verilator's default context (which lives for the
/// whole program) once the model is gone. enter() makes the model's context current for
/// its destruction; call it from the owner's destructor.
class ThreadContextGuard {
 public:
  explicit ThreadContextGuard(VerilatedContext& own) : own_(own) {}
  ThreadContextGuard(const ThreadContextGuard&) = delete;
  ThreadContextGuard& operator=(const ThreadContextGuard&) = delete;
  ~ThreadContextGuard() { ::Verilated::threadContextp(::Verilated::defaultContextp()); }

  void enter() { ::Verilated::threadContextp(&own_); }

 private:
  VerilatedContext& own_;
};

}  // namespace specular
