// The cost of writing the pin model's trace with the FST writer Verilator ships
// (/usr/share/verilator/include/gtkwave/fstapi.c), for docs/performance.md (issue 27):
// the value changes of a VCD that specular_tb wrote are read into memory first
// (untimed), then emitted through fstapi with the settings Verilator's own FST writer
// uses (LZ4 value-change packing, 1 ps), and only that is timed (user CPU of this
// process, getrusage): what an sc_trace_file of our own over fstapi would spend in
// fstapi, with no VCD text written or parsed. A measurement tool, not built by CMake:
//
//   g++ -O2 -I/usr/share/verilator/include/gtkwave -DFST_CONFIG_INCLUDE='"fst_config.h"'
//       bench/fst_writer/fst_writer_cost.cpp
//       -x c /usr/share/verilator/include/gtkwave/{fstapi,lz4,fastlz}.c -lz -lpthread
//       -o /tmp/fst_writer_cost        (one command)
//   /tmp/fst_writer_cost run.vcd out.fst   # prints "fstapi_user_s <s> fst_bytes <n>"
//
// SystemC's VCD: $scope/$upscope, "$var wire W id name [range] $end", "$var real 1 id
// name $end", "#T", "0id"/"1id", "bVALUE id", "rVALUE id".
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

extern "C" {
#include "fstapi.h"
}

namespace {
double user_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec) + static_cast<double>(usage.ru_utime.tv_usec) * 1e-6;
}

struct Var {
  int width;
  bool real;
  std::string name;
};
struct Event {  // a time change (var < 0) or a value change
  long var;
  unsigned long long time;
  std::string value;
};
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fst_writer_cost IN.vcd OUT.fst\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << "fst_writer_cost: cannot read '" << argv[1] << "'\n";
    return 2;
  }
  std::vector<Var> vars;
  std::vector<std::string> scope_ops;  // "+name" / "-" before var i: kept with the var
  std::vector<std::vector<std::string>> scopes_before;
  std::unordered_map<std::string, long> ids;
  std::vector<Event> events;
  std::vector<std::string> pending_scopes;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (header) {
      std::istringstream words(line);
      std::string w;
      words >> w;
      if (w == "$scope") {
        std::string kind, name;
        words >> kind >> name;
        pending_scopes.push_back("+" + name);
      } else if (w == "$upscope") {
        pending_scopes.push_back("-");
      } else if (w == "$var") {
        std::string type, id, name, range;
        int width = 0;
        words >> type >> width >> id >> name >> range;
        if (range != "$end") name += range;
        if (ids.count(id)) continue;  // an alias: one handle
        ids[id] = static_cast<long>(vars.size());
        vars.push_back({width, type == "real", name});
        scopes_before.push_back(pending_scopes);
        pending_scopes.clear();
      } else if (w == "$enddefinitions") {
        header = false;
      }
      continue;
    }
    if (line[0] == '#') {
      events.push_back({-1, std::strtoull(line.c_str() + 1, nullptr, 10), ""});
    } else if (line[0] == 'b' || line[0] == 'r') {
      const std::size_t space = line.find(' ');
      const auto it = ids.find(line.substr(space + 1));
      if (it != ids.end()) events.push_back({it->second, 0, line.substr(1, space - 1)});
    } else if (line[0] == '0' || line[0] == '1' || line[0] == 'x' || line[0] == 'z') {
      const auto it = ids.find(line.substr(1));
      if (it != ids.end()) events.push_back({it->second, 0, line.substr(0, 1)});
    }
  }
  // Vector values padded to their width as fstapi wants them (VCD drops leading zeros).
  for (Event& e : events)
    if (e.var >= 0 && !vars[e.var].real && static_cast<int>(e.value.size()) < vars[e.var].width)
      e.value.insert(0, vars[e.var].width - e.value.size(), e.value[0] == '1' ? '0' : e.value[0]);

  const double start = user_seconds();
  void* fst = fstWriterCreate(argv[2], 1);
  if (fst == nullptr) {
    std::cerr << "fst_writer_cost: cannot write '" << argv[2] << "'\n";
    return 2;
  }
  fstWriterSetPackType(fst, FST_WR_PT_LZ4);
  fstWriterSetTimescaleFromString(fst, "1ps");
  std::vector<fstHandle> handles;
  for (std::size_t i = 0; i < vars.size(); ++i) {
    for (const std::string& op : scopes_before[i]) {
      if (op == "-") fstWriterSetUpscope(fst);
      else fstWriterSetScope(fst, FST_ST_VCD_MODULE, op.c_str() + 1, nullptr);
    }
    handles.push_back(fstWriterCreateVar(fst, vars[i].real ? FST_VT_VCD_REAL : FST_VT_VCD_WIRE,
                                         FST_VD_IMPLICIT, vars[i].real ? 64 : vars[i].width,
                                         vars[i].name.c_str(), 0));
  }
  for (const Event& e : events) {
    if (e.var < 0) {
      fstWriterEmitTimeChange(fst, e.time);
    } else if (vars[e.var].real) {
      const double value = std::strtod(e.value.c_str(), nullptr);
      fstWriterEmitValueChange(fst, handles[e.var], &value);
    } else {
      fstWriterEmitValueChange(fst, handles[e.var], e.value.c_str());
    }
  }
  fstWriterClose(fst);
  const double seconds = user_seconds() - start;
  std::ifstream out(argv[2], std::ios::binary | std::ios::ate);
  std::printf("fstapi_user_s %.3f fst_bytes %lld vars %zu changes %zu\n", seconds,
              static_cast<long long>(out.tellg()), vars.size(), events.size());
  return 0;
}
