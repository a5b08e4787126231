// A falling edge of pin 28 shown to a verilated synchronous device without an eval()
// (docs/performance/rtl.md, "Specialised verilation"). Nothing in specular_device_sync reacts
// to the falling edge: Verilator 5.006 evaluates it only to remember that the clock was
// low, in the root's `__Vtrigrprev__TOP__pin28_clk`, so that the next rising edge
// triggers. Where the model has that member, writing it is that eval() without the
// scheduler's ~150 instructions; where it has not (another Verilator), the eval() runs.
// Used for the specialised models only; tests/test_long_rtl_fixed.cpp proves them equal
// to Core on every input.
#pragma once

#include <type_traits>

namespace specular {

template <class Root, class = void>
struct RemembersClockLevel : std::false_type {};
template <class Root>
struct RemembersClockLevel<Root, std::void_t<decltype(std::declval<Root&>().__Vtrigrprev__TOP__pin28_clk)>>
    : std::true_type {};

/// Sets pin 28 low; evaluates `top` only if its root cannot be told directly.
template <class Top>
void show_clock_low(Top& top) {
  top.pin28_clk = 0;
  using Root = std::remove_pointer_t<decltype(top.rootp)>;
  if constexpr (RemembersClockLevel<Root>::value)
    top.rootp->__Vtrigrprev__TOP__pin28_clk = 0;
  else
    top.eval();
}

}  // namespace specular
