// A consumer of the installed IP (scripts/verify/consumer_check.sh builds it against
// `cmake --install` and through add_subdirectory): a CPU thread runs one operation
// on the TLM `lt` target and checks it against the double reference.
// The lines between the [example] markers are the ten-line example of docs/tlm.md
// (a test keeps the two equal).
#include <cmath>
#include <iostream>

// [example]
#include <specular/specular.h>
#include <tlm_utils/simple_initiator_socket.h>

struct Cpu : sc_core::sc_module {
  tlm_utils::simple_initiator_socket<Cpu, 32> bus{"bus"};
  tlm_utils::tlm_quantumkeeper keeper;
  specular::SpecularDriver ip{bus, 0x0, keeper};  // the IP's base address on `bus`
  std::array<std::int32_t, 3> out{};               // pins 24–26, S18.13
  SC_CTOR(Cpu) { SC_THREAD(run); }
  void run() {  // writes N, R, G, B, COS, then START; reads OUT_R, OUT_G, OUT_B
    out = ip.compute({/*cos*/ 64500, /*n*/ 40, /*rgb*/ {255, 200, 100}});
  }
};

int sc_main(int, char*[]) {
  Cpu cpu("cpu");
  specular::SpecularLtTarget specular("specular");  // default Config, 10 ns clock
  sc_core::sc_signal<bool> irq("irq");
  cpu.bus.bind(specular.socket);
  specular.done_irq(irq);
  sc_core::sc_start();
  // [example]

  const auto ref = specular::reference::evaluate(64500 / 65536.0, 40, {255, 200, 100},
                                                 specular::Normalisation::patent,
                                                 specular::Saturation::clamp, 16);
  const double k = specular::reference::k(40, specular::Normalisation::patent);
  bool pass = true;
  for (int ch = 0; ch < 3; ++ch) {
    const double got = cpu.out[ch] / 8192.0;
    const double tolerance = specular::reference::out_tolerance(k, ch == 0 ? 255 : ch == 1 ? 200 : 100,
                                                                1.0 / 8192);
    std::cout << "channel " << ch << ": " << got << " (reference " << ref.out_ref[ch] << ")\n";
    pass = pass && std::fabs(got - ref.out_ref[ch]) <= tolerance;
  }
  std::cout << (pass ? "consumer: PASS" : "consumer: FAIL") << std::endl;
  return pass ? 0 : 1;
}
