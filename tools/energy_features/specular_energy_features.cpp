// specular_energy_features: the energy model's features of each operation of an operand
// stream (issue 61, docs/energy/calibration.md), computed by the C++ the model itself
// charges with (specular::energy::operation_features), so that the fit
// (scripts/flows/energy/model/fit.py) and the model cannot differ.
//
//   specular_energy_features [--model] STREAM [OUT]
//
// STREAM: one operation a line, `cos n r g b` in hex (gatesim.sh --stimulus's format,
// specular_variant_vectors' first five columns; cos a code of 17 bits, 0x10000 = 1.0;
// further columns ignored). Each runs through specular::Core at the patent's policies
// (the gate-level testbenches' patent/patent/clamp), starting from the registers after
// reset. OUT (default stdout): a TSV, a header `index` and the feature names, then one
// line per operation. --model adds the model's pJ of each operation as compiled
// (OperationEnergy with calibration.h): columns pj_synchronous and pj_drawn.
// Exit status: 0 written, 2 bad input (the line and the value named).
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "specular/core.h"
#include "specular/energy/operation_energy.h"
#include "specular/energy/operation_features.h"
#include "usage_error.h"

namespace {

using BadInput = specular::tb::UsageError;

specular::code_t field(const std::string& text, const char* name, long long lo, long long hi,
                       const std::string& where) {
  std::size_t used = 0;
  long long v = -1;
  try {
    v = std::stoll(text, &used, 16);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || v < lo || v > hi) {
    std::ostringstream m;
    m << where << ": " << name << " '" << text << "' is not a hex code in [0x" << std::hex << lo
      << ", 0x" << hi << "]";
    throw BadInput(m.str());
  }
  return static_cast<specular::code_t>(v);
}

/// The features (and with `model` the model's pJ) of each operation of `stream`, as TSV
/// to `out_path` (empty: standard output).
int features(const std::string& stream, const std::string& out_path, bool model) {
  std::ifstream in(stream);
  if (!in) throw BadInput("cannot read '" + stream + "'");
  const specular::Core core;  // the patent's widths and policies
  const specular::Formats& f = core.formats();
  std::ostringstream text;
  text << "index";
  for (const char* name : specular::energy::feature_names) text << '\t' << name;
  if (model) text << "\tpj_synchronous\tpj_drawn";
  text << '\n';
  specular::energy::OperationEnergy synchronous(specular::energy::Calibration::synchronous_device, f);
  specular::energy::OperationEnergy drawn(specular::energy::Calibration::drawn_device, f);
  specular::energy::RegisterState before = specular::energy::reset_state();
  std::string line;
  int number = 0, index = 0;
  {
    while (std::getline(in, line)) {
      ++number;
      std::istringstream words(line);
      std::vector<std::string> w;
      for (std::string s; words >> s;) w.push_back(s);
      if (w.empty()) continue;
      const std::string where = stream + ":" + std::to_string(number);
      if (w.size() < 5) throw BadInput(where + ": " + std::to_string(w.size()) + " fields, expected 'cos n r g b' in hex");
      specular::Operands op;
      op.cos = field(w[0], "cos", 0, 0x10000, where);
      op.n = field(w[1], "n", 1, 1000, where);
      static const char* channels[3] = {"R", "G", "B"};
      for (int ch = 0; ch < 3; ++ch) op.rgb[ch] = field(w[2 + ch], channels[ch], 0, 255, where);
      const specular::energy::RegisterState after{op, core.run(op)};
      const specular::energy::Features x = specular::energy::operation_features(f, before, after);
      before = after;
      text << index++;
      for (double v : x) text << '\t' << v;
      if (model) text << '\t' << synchronous.next(after.in, after.r) << '\t' << drawn.next(after.in, after.r);
      text << '\n';
    }
  }
  if (index == 0) throw BadInput("'" + stream + "' holds no operation");
  if (!out_path.empty()) {
    std::ofstream out(out_path);
    out << text.str();
    if (!out) throw BadInput("cannot write '" + out_path + "'");
  } else {
    std::cout << text.str();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  specular::cli::Command app{"The energy model's features of each operation of an operand stream, computed by the C++\n"
                             "the model charges with (docs/energy/calibration.md).",
                             "specular_energy_features"};
  specular::cli::house_rules(app, "Exit status: 0 written, 2 bad input (the line and the value named).");
  std::string stream, out_path;
  bool model = false;
  app.add_option("STREAM", stream, "'cos n r g b' in hex per line")->required();
  app.add_option("OUT", out_path, "the features' TSV (default: standard output)");
  app.add_flag("--model", model, "also each operation's pJ by the compiled model, both calibrations");
  return specular::cli::run(app, argc, argv, [&] { return features(stream, out_path, model); });
}
