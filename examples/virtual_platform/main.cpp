// specular_vp: the example virtual platform. A CPU renders a sphere's specular
// highlight for n = 1, 10, 100, 1000 side by side by driving the specular IP over a
// bus, and the frame buffer is written as a binary PPM (P6).
//
//   specular_vp --out FILE.ppm [--size N] [--policy patent|energy|none]
//               [--constants patent|minimax-half|minimax]
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include "platform.h"

namespace {

using namespace specular;
using namespace specular::vp;

constexpr int exit_usage = 2;

const char* usage =
    "usage: specular_vp --out FILE.ppm [--size N] [--policy patent|energy|none]\n"
    "                   [--constants patent|minimax-half|minimax]\n"
    "  --out FILE      the image: 4 panels of N x N pixels side by side, binary PPM (P6)\n"
    "  --size N        panel size in pixels, 16..1024 (default 256)\n"
    "  --policy P      the IP's ROM 38 contents (default none: K = 1, so every panel's\n"
    "                  highlight peaks at the light's intensity; patent: 2pi/(n+2),\n"
    "                  whose n = 1000 highlight is nearly black; energy: (n+2)/(2pi))\n"
    "  --constants C   the IP's pins 19 (h), 20 (a) and ROM 38's scale s (default\n"
    "                  patent: 1/2, 1, 1; minimax-half, minimax: docs/study.md)\n";

struct Arguments {
  std::string out;
  int size = 256;
  Normalisation policy = Normalisation::none;
  Constants constants = Constants::patent;
};

[[noreturn]] void usage_error(const std::string& message) {
  std::cerr << "specular_vp: error: " << message << "\n" << usage;
  std::exit(exit_usage);
}

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help") {
      std::cout << usage;
      std::exit(0);
    }
    if (option != "--out" && option != "--size" && option != "--policy" && option != "--constants")
      usage_error("unknown option '" + option + "'");
    if (i + 1 >= argc) usage_error(option + " needs a value");
    const std::string value = argv[++i];
    if (option == "--out") {
      a.out = value;
    } else if (option == "--size") {
      char* end = nullptr;
      const long size = std::strtol(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || size < 16 || size > 1024)
        usage_error("--size = '" + value + "' is not an integer in [16, 1024]");
      a.size = static_cast<int>(size);
    } else if (option == "--constants") {
      try {
        a.constants = parse_constants(value);
      } catch (const std::invalid_argument& e) {
        usage_error(std::string("--constants: ") + e.what());
      }
    } else if (value == "patent") {
      a.policy = Normalisation::patent;
    } else if (value == "energy") {
      a.policy = Normalisation::energy;
    } else if (value == "none") {
      a.policy = Normalisation::none;
    } else {
      usage_error("--policy = '" + value + "' is not one of: patent, energy, none");
    }
  }
  if (a.out.empty()) usage_error("--out FILE is required");
  return a;
}

/// P6, written to FILE.tmp and renamed: no file that looks complete unless it is.
bool write_ppm(const std::string& path, const Frame& frame, const std::vector<unsigned char>& memory) {
  const std::string temp = path + ".tmp";
  {
    std::ofstream out(temp, std::ios::binary);
    out << "P6\n" << frame.width() << ' ' << frame.size << "\n255\n";
    out.write(reinterpret_cast<const char*>(&memory[frame.frame_buffer() - memory_base]),
              static_cast<std::streamsize>(3ull * frame.width() * frame.size));
    out.flush();
    if (!out) {
      std::remove(temp.c_str());
      return false;
    }
  }
  return std::rename(temp.c_str(), path.c_str()) == 0;
}

}  // namespace

int sc_main(int argc, char** argv) {
  const Arguments args = parse(argc, argv);
  Frame frame;
  frame.size = args.size;
  Config config;
  config.normalisation = args.policy;
  config.constants = args.constants;

  Cpu cpu("cpu", frame);
  Router bus("bus", {{memory_base, frame.memory_bytes(), "to_memory"},
                     {ip_base, map_size, "to_specular"}});
  Memory memory("memory", frame.memory_bytes());
  SpecularLtTarget ip("specular", config);
  sc_core::sc_signal<bool> irq("specular_irq");
  cpu.socket.bind(bus.socket);
  bus.output(0).bind(memory.socket);
  bus.output(1).bind(ip.socket);
  ip.done_irq(irq);

  sc_core::sc_start();
  if (!cpu.failure.empty()) {
    std::cerr << "specular_vp: error: " << cpu.failure << "\n";
    return 1;
  }
  if (!write_ppm(args.out, frame, memory.contents())) {
    std::cerr << "specular_vp: error: cannot write '" << args.out << "'\n";
    return 1;
  }
  std::cout << "specular_vp: " << Frame::panel_count << " panels of " << frame.size << "x"
            << frame.size << " (n = 1, 10, 100, 1000): " << cpu.operations
            << " operations through the IP in " << cpu.ip_bursts << " BATCH_COS bursts; simulated "
            << cpu.finished_at << " (IP annotated " << cpu.ip_busy << "); wrote " << args.out
            << "\n";
  // What the frame cost the IP (issue 61, docs/energy.md), at the kernel's end time.
  const energy::EnergyTally e = ip.energy();
  const double pixels = static_cast<double>(Frame::panel_count) * frame.size * frame.size;
  std::cout << "specular_vp: energy " << e.total_pj() / pixels << " pJ per pixel, " << e.total_pj() / 1e6
            << " uJ per frame (operations " << e.operation_pj / 1e6 << " uJ, register reads and writes "
            << (e.read_pj + e.write_pj) / 1e6 << " uJ, " << e.clocks << " clocks " << e.clock_pj / 1e6
            << " uJ; the synchronous device's gate-level figures), mean power "
            << e.total_pj() / (cpu.finished_at.to_seconds() * 1e9) << " mW\n";
  return 0;
}
