// specular_vp: the example virtual platform. A CPU renders a sphere's specular
// highlight for n = 1, 10, 100, 1000 side by side by driving the specular IP over a
// bus, and the frame buffer is written as a binary PPM (P6).
//
//   specular_vp --out FILE.ppm [--size N] [--policy patent|energy|none]
//               [--constants patent|minimax-half|minimax]      (--help: what each does)
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include "platform.h"

namespace {

using namespace specular;
using namespace specular::vp;

constexpr int exit_usage = 2;

struct Arguments {
  std::string out;
  int size = 256;
  Normalisation policy = Normalisation::none;
  Constants constants = Constants::patent;
};

/// The command line, declared once with CLI11 (as the project's tools): --help from the
/// declarations, a bad value one line naming it and the allowed values, exit status 2.
Arguments parse(int argc, char** argv) {
  Arguments a;
  CLI::App app{"The example virtual platform: a CPU renders a sphere's specular highlight for n = 1, 10, "
               "100, 1000 side by side through the specular IP over a bus, and writes the frame buffer "
               "as a binary PPM (P6).",
               "specular_vp"};
  app.set_version_flag("--version", std::string("specular_vp ") + SPECULAR_EXAMPLE_VERSION,
                       "print the version and exit");
  app.add_option("--out", a.out, "the image: 4 panels of N x N pixels side by side, binary PPM (P6)")
      ->required();
  app.add_option("--size", a.size, "panel size in pixels, 16..1024 (default 256)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const long size = std::strtol(text.c_str(), &end, 10);  // decimal: CLI11 reads 010 as octal
            if (text.empty() || *end != '\0' || size < 16 || size > 1024)
              return "'" + text + "' is not an integer in [16, 1024]";
            text = std::to_string(size);
            return {};
          },
          "N"));
  static const std::map<std::string, Normalisation> policies{
      {"patent", Normalisation::patent}, {"energy", Normalisation::energy}, {"none", Normalisation::none}};
  app.add_option_function<std::string>(
         "--policy", [&](const std::string& name) { a.policy = policies.at(name); },
         "the IP's ROM 38 contents (default none: K = 1, so every panel's highlight peaks at the "
         "light's intensity; patent: 2pi/(n+2), whose n = 1000 highlight is nearly black; energy: "
         "(n+2)/(2pi))")
      ->check(CLI::Validator(
          [](std::string& name) -> std::string {
            return policies.count(name) ? "" : "'" + name + "' is not one of: patent, energy, none";
          },
          "patent|energy|none"));
  app.add_option_function<std::string>(
         "--constants", [&](const std::string& text) { a.constants = parse_constants(text); },
         "the IP's pins 19 (h), 20 (a) and ROM 38's scale s (default patent: 1/2, 1, 1; minimax-half, "
         "minimax: docs/study.md)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            try {
              parse_constants(text);
              return {};
            } catch (const std::invalid_argument& e) {
              return e.what();
            }
          },
          "patent|minimax-half|minimax"));
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    std::exit(app.exit(e));  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::cerr << "specular_vp: error: " << e.what() << "\n";
    std::exit(exit_usage);
  }
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
  ip.set_energy_model(true);  // the frame's energy is reported (issue 61)

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
