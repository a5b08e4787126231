// specular_prove: the exhaustive proofs as a command of their own (issue 25). Every cos
// code of register 1 × every n in 1..1000 × every buildable device (normalisation ×
// saturation × constants) of one model — rtl, rtl-sync (the verilated twins as plain
// C++ cycle models, every device in one process), pin or tlm (SystemC: one device per
// process, --device) — against the bit-accurate Core: every result field equal and
// 35 rising when the model's timing table says. --shard I/N splits by n as
// specular_tb --sweep and tests/support/operation_shard.h do ((n - 1) mod N = I);
// --partial writes a partial result and --merge turns a complete set into the
// unsharded proof's report, refusing a missing, duplicated or mismatched shard.
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli.h"
#include "output_file.h"
#include "partial_set.h"
#include "progress.h"
#include "run_models.h"
#include "scoreboard.h"
#include "shard.h"
#include "specular/core.h"
#include "specular/systemc.h"
#include "usage_error.h"
#ifdef SPECULAR_HAS_RTL_TWIN
#include "specular/twin/rtl_cycle_model.h"
#include "specular/twin/rtl_sync_cycle_model.h"
#endif

namespace specular {
namespace tb {
namespace {

constexpr const char* prove_kind = "specular_prove partial result";

/// One device's proof (or its share of n).
struct DeviceProof {
  std::string name;               ///< normalisation/saturation/constants
  bool buildable = true;          ///< false: the core refuses it (the model must too)
  bool refusal_ok = true;         ///< unbuildable: the model refused it as well
  std::size_t operations = 0;
  std::size_t mismatches = 0;     ///< a result field differs from the core's
  std::size_t off_timing = 0;     ///< 35 rose at another time than the table's
  std::optional<std::size_t> first_at;  ///< smallest index of a miss (n-major)
  std::string first_miss;         ///< what differed there
  std::uint64_t checksum = 0;     ///< Summary::checksum's hash, summed
  bool pass() const { return buildable ? (mismatches == 0 && off_timing == 0) : refusal_ok; }
};

std::vector<Config> every_device() {
  std::vector<Config> devices;
  for (Normalisation nm : {Normalisation::patent, Normalisation::energy, Normalisation::none,
                           Normalisation::device_energy})
    for (Saturation sat : {Saturation::clamp, Saturation::literal})
      for (Constants k : {Constants::patent, Constants::minimax_half, Constants::minimax}) {
        Config c;
        c.normalisation = nm;
        c.saturation = sat;
        c.constants = k;
        devices.push_back(c);
      }
  return devices;
}

std::string device_name(const Config& c) {
  return std::string(to_string(c.normalisation)) + "/" + to_string(c.saturation) + "/" +
         to_string(c.constants);
}

std::string device_names() {
  std::string names;
  for (const Config& c : every_device()) names += (names.empty() ? "" : ", ") + device_name(c);
  return names;
}

bool core_builds(const Config& config) {
  try {
    const Core core(config);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

std::string differing_fields(const Result& a, const Result& b) {
  std::string fields;
  if (a.reg1 != b.reg1) fields += " reg1";
  if (a.reg9_pass1 != b.reg9_pass1) fields += " reg9_pass1";
  if (a.reg9_pass2 != b.reg9_pass2) fields += " reg9_pass2";
  if (a.rom38_k != b.rom38_k) fields += " rom38_k";
  if (a.norm39 != b.norm39) fields += " norm39";
  if (a.out != b.out) fields += " out";
  return fields;
}

struct ProveOptions {
  Model model = Model::rtl;
  std::string device = "all";
  code_t cos_stride = 1;          ///< every K-th cos code (tests: a quick proof); 1 = every one
  Shard shard;
  std::string partial_path;
  bool quiet = false;  ///< no progress line even on a terminal
  std::vector<std::string> merge_files;  ///< --merge FILE...: the partial results to merge
};

/// Operations checked so far over every device of the run, as the progress line of
/// every long run (progress.h: on a terminal only, not with --quiet).
struct ProofProgress {
  Progress line;
  std::uint64_t done = 0;
  void add(std::size_t count) {
    done += count;
    line.update(done);
  }
};

/// Operation index of (n, cos code) in the unsharded proof of one device.
std::size_t op_index(code_t n, code_t code, code_t stride, code_t codes_per_n) {
  return static_cast<std::size_t>((n - n_min) * codes_per_n + code / stride);
}

/// Every operand of one device's share, in n-major order, chunk by chunk.
class ProofOperands {
 public:
  ProofOperands(const Formats& formats, code_t stride, const Shard& shard)
      : one_(formats.cos.one()), stride_(stride), shard_(shard) {}
  code_t codes_per_n() const { return one_ / stride_ + 1; }
  bool next(std::vector<Operands>& chunk, std::size_t max) {
    chunk.clear();
    while (chunk.size() < max && n_ <= static_cast<code_t>(n_max)) {
      if (!shard_has_n(static_cast<unsigned>(n_), shard_)) {
        ++n_;
        continue;
      }
      // R, G, B walk through 0..255 with n (as tests/test_long_rtl_exhaustive.cpp).
      const std::array<code_t, 3> rgb = {(n_ * 1) % 256, (n_ * 7 + 3) % 256, (n_ * 101 + 250) % 256};
      chunk.push_back(Operands{code_, n_, rgb});
      code_ += stride_;
      if (code_ > one_) {
        code_ = 0;
        ++n_;
      }
    }
    return !chunk.empty();
  }

 private:
  code_t one_, stride_;
  Shard shard_;
  code_t n_ = n_min, code_ = 0;
};

/// Compares one batch with the core and adds it to `proof`.
void check_batch(const Core& core, const std::vector<Operands>& batch, const std::vector<Result>& out,
                 const std::vector<double>& cycles, double periods, code_t stride, code_t per_n,
                 DeviceProof& proof, ProofProgress& progress) {
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const std::size_t index = op_index(batch[i].n, batch[i].cos, stride, per_n);
    const std::string fields = differing_fields(out[i], core.run(batch[i]));
    const bool late = cycles[i] != periods;
    if (!fields.empty()) ++proof.mismatches;
    if (late) ++proof.off_timing;
    if ((!fields.empty() || late) && (!proof.first_at || index < *proof.first_at)) {
      proof.first_at = index;
      proof.first_miss = "n " + std::to_string(batch[i].n) + ", cos code " + std::to_string(batch[i].cos) +
                         ":" + (fields.empty() ? "" : fields) + (late ? " cycles " + std::to_string(cycles[i]) : "");
    }
    proof.checksum += result_hash(index, out[i], cycles[i]);
  }
  proof.operations += batch.size();
  progress.add(batch.size());
}

#ifdef SPECULAR_HAS_RTL_TWIN
template <class Twin>
DeviceProof prove_twin(const Config& config, const ProveOptions& o, double periods,
                       ProofProgress& progress) {
  DeviceProof proof;
  proof.name = device_name(config);
  if (!core_builds(config)) {
    proof.buildable = false;
    try {
      Twin refused(config);
      proof.refusal_ok = false;  // the twin built a device the core refuses
    } catch (const std::invalid_argument&) {
    }
    return proof;
  }
  const Core core(config);
  Twin twin(config);
  twin.reset();
  ProofOperands source(core.formats(), o.cos_stride, o.shard);
  std::vector<Operands> batch;
  std::vector<Result> out;
  while (source.next(batch, 65537)) {
    twin.run_batch(batch, out);
    check_batch(core, batch, out, twin.cycles(), periods, o.cos_stride, source.codes_per_n(), proof,
                progress);
  }
  return proof;
}
#endif

DeviceProof prove_systemc(const Config& config, const ProveOptions& o, ProofProgress& progress) {
  DeviceProof proof;
  proof.name = device_name(config);
  if (!core_builds(config)) {
    proof.buildable = false;  // the pin and TLM models build from the core's tables
    return proof;
  }
  const Core core(config);
  ProofOperands source(core.formats(), o.cos_stride, o.shard);
  RunSettings settings;
  settings.model = o.model;
  settings.config = config;
  const double periods = latency_cycles(o.model);
  run_operations(
      settings, [&](std::vector<Operands>& chunk, std::size_t max) { return source.next(chunk, max); },
      [&](const std::vector<Operands>& chunk, const std::vector<Result>& results,
          const std::vector<double>& cycles) {
        check_batch(core, chunk, results, cycles, periods, o.cos_stride, source.codes_per_n(), proof,
                    progress);
      });
  return proof;
}

Json proof_json(const DeviceProof& p) {
  char checksum[24];
  std::snprintf(checksum, sizeof checksum, "0x%016llx", static_cast<unsigned long long>(p.checksum));
  Json j{{"device", p.name}, {"buildable", p.buildable}, {"refusal_ok", p.refusal_ok},
         {"operations", p.operations}, {"mismatches", p.mismatches}, {"off_timing", p.off_timing}};
  j["first_miss"] = p.first_at ? Json{{"at", *p.first_at}, {"what", p.first_miss}} : Json(nullptr);
  j["checksum"] = checksum;
  j["pass"] = p.pass();
  return j;
}

DeviceProof proof_from_json(const Json& j) {
  DeviceProof p;
  p.name = j.at("device").get<std::string>();
  p.buildable = j.at("buildable").get<bool>();
  p.refusal_ok = j.at("refusal_ok").get<bool>();
  p.operations = j.at("operations").get<std::size_t>();
  p.mismatches = j.at("mismatches").get<std::size_t>();
  p.off_timing = j.at("off_timing").get<std::size_t>();
  if (!j.at("first_miss").is_null()) {
    p.first_at = j.at("first_miss").at("at").get<std::size_t>();
    p.first_miss = j.at("first_miss").at("what").get<std::string>();
  }
  p.checksum = std::stoull(j.at("checksum").get<std::string>(), nullptr, 16);
  return p;
}

/// The report: one line per device and the verdict. The same for a run and a merge.
int report(const std::vector<DeviceProof>& proofs, const Json& settings, std::size_t expected_per_device,
           std::ostream& out) {
  bool pass = true;
  std::uint64_t checksum = 0;
  std::size_t operations = 0;
  out << "specular_prove: model " << settings.at("model").get<std::string>() << " against the core, "
      << "every " << (settings.at("cos_stride").get<long long>() == 1 ? std::string("")
                      : std::to_string(settings.at("cos_stride").get<long long>()) + "th ")
      << "cos code x n 1..1000, " << proofs.size() << " device(s)\n";
  for (const DeviceProof& p : proofs) {
    out << "  " << p.name << ": ";
    if (!p.buildable)
      out << (p.refusal_ok ? "refused, as the core refuses it" : "BUILT, but the core refuses it");
    else
      out << p.operations << " operations, " << p.mismatches << " differ, " << p.off_timing
          << " off timing" << (p.first_at ? ", first at " + p.first_miss : "")
          << (p.operations != expected_per_device ? " (INCOMPLETE: expected " + std::to_string(expected_per_device) + ")" : "");
    out << (p.pass() && (!p.buildable || p.operations == expected_per_device) ? "  PASS" : "  FAIL") << '\n';
    pass = pass && p.pass() && (!p.buildable || p.operations == expected_per_device);
    checksum += p.checksum;
    operations += p.operations;
  }
  char text[24];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(checksum));
  out << "proof: " << operations << " operations, results checksum " << text << ": "
      << (pass ? "PASS" : "FAIL") << '\n';
  return pass ? 0 : 1;
}

/// Declares the options on `app` (run_support/cli.h), each writing into `o`.
void add_prove_options(specular::cli::Command& app, ProveOptions& o) {
  cli::add_parsed(app, "--model", o.model,
                  [](const std::string& v) {
                    const Model m = parse_model(v);
                    if (m == Model::core)
                      throw UsageError("'core' is the reference itself; one of: rtl, rtl-sync, pin, tlm");
                    return m;
                  },
                  "rtl, rtl-sync: the verilated twins as C++ cycle models, every device in one process; "
                  "pin, tlm: SystemC, one device per process (--device); required but with --merge")
      ->type_name("rtl|rtl-sync|pin|tlm");
  app.add_option("--device", o.device,
                 "NORMALISATION/SATURATION/CONSTANTS, one of: " + device_names() +
                     "; or all (default, rtl and rtl-sync only)")
      ->type_name("NAME|all");
  cli::add_parsed(app, "--shard", o.shard,
                  [](const std::string& v) {
                    const Shard shard = parse_shard(v);
                    if (shard.count > n_max - n_min + 1)
                      throw UsageError("N = " + std::to_string(shard.count) +
                                       " is outside the allowed range [1, 1000] (split by n)");
                    return shard;
                  },
                  "the n with (n - 1) mod N = I (tests/support/operation_shard.h's split)")
      ->type_name("I/N");
  app.add_option("--partial", o.partial_path, "write this run's partial result (JSON) for --merge")
      ->type_name("FILE")
      ->check(cli::file_name());
  app.add_option("--cos-stride", o.cos_stride, "every K-th cos code (default 1 = every code)")
      ->type_name("K")
      ->check(cli::integer_in(1, 65536, "K"));
  app.add_flag("--quiet", o.quiet, "no progress line (drawn on standard error only when it is a terminal)");
  app.add_option("--merge", o.merge_files,
                 "turn a complete set of partial results into the unsharded proof's report, refusing a "
                 "missing, duplicated or mismatched shard (nothing else with it)")
      ->type_name("FILE")
      ->expected(1, -1);
}

int run_prove(const ProveOptions& o, bool model_given, std::ostream& out, std::ostream& err) {
  if (!o.merge_files.empty()) {
    const std::vector<std::string>& files = o.merge_files;
    const std::vector<PartialFile> parts = read_complete_set(files, prove_kind);
    std::vector<DeviceProof> total;
    double cpu = 0;
    for (const PartialFile& part : parts) {
      const Json& devices = part.json.at("summary").at("devices");
      cpu += part.json.at("timing").value("cpu_seconds", 0.0);
      for (std::size_t d = 0; d < devices.size(); ++d) {
        const DeviceProof p = proof_from_json(devices.at(d));
        if (total.size() <= d) {
          total.push_back(p);
          continue;
        }
        DeviceProof& t = total[d];
        t.operations += p.operations;
        t.mismatches += p.mismatches;
        t.off_timing += p.off_timing;
        t.checksum += p.checksum;
        t.refusal_ok = t.refusal_ok && p.refusal_ok;
        if (p.first_at && (!t.first_at || *p.first_at < *t.first_at)) {
          t.first_at = p.first_at;
          t.first_miss = p.first_miss;
        }
      }
    }
    const Json& settings = parts.front().json.at("settings");
    const int status = report(total, settings, settings.at("operations_per_device").get<std::size_t>(), out);
    err << "specular_prove --merge: " << parts.size() << " shard(s), CPU " << cpu << " s in all\n";
    return status;
  }

  if (!model_given) throw UsageError("--model is required: one of rtl, rtl-sync, pin, tlm");
  std::vector<Config> devices;
  for (const Config& c : every_device())
    if (o.device == "all" || o.device == device_name(c)) devices.push_back(c);
  if (devices.empty())
    throw UsageError("--device: '" + o.device + "' is not one of: " + device_names() + ", all");
  const bool systemc = o.model == Model::pin || o.model == Model::tlm;
  if (systemc && devices.size() != 1)
    throw UsageError("--model " + std::string(to_string(o.model)) +
                     " elaborates SystemC once per process: give --device NAME (one of: " + device_names() + ")");
#ifndef SPECULAR_HAS_RTL_TWIN
  if (!systemc) throw UsageError("this build has no RTL twin (Verilator was not found)");
#endif
  std::optional<AtomicOutputStream> partial_file;
  if (!o.partial_path.empty()) partial_file.emplace(o.partial_path, "--partial");

  const Formats formats;
  const std::size_t per_device = static_cast<std::size_t>(formats.cos.one() / o.cos_stride + 1) * (n_max - n_min + 1);
  std::size_t shard_per_device = 0;
  for (unsigned n = n_min; n <= n_max; ++n) shard_per_device += shard_has_n(n, o.shard) ? 1 : 0;
  shard_per_device *= static_cast<std::size_t>(formats.cos.one() / o.cos_stride + 1);

  const auto started = std::chrono::steady_clock::now();
  ProofProgress progress{Progress(std::cerr, shard_per_device * devices.size(), progress_wanted(o.quiet))};
  std::vector<DeviceProof> proofs;
  for (const Config& c : devices) {
    if (systemc) proofs.push_back(prove_systemc(c, o, progress));
#ifdef SPECULAR_HAS_RTL_TWIN
    else if (o.model == Model::rtl) proofs.push_back(prove_twin<RtlCycleModel>(c, o, latency_cycles(Model::rtl), progress));
    else proofs.push_back(prove_twin<RtlSyncCycleModel>(c, o, latency_cycles(Model::rtl_sync), progress));
#endif
  }
  progress.line.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  Json settings{{"model", to_string(o.model)}, {"device", o.device}, {"cos_stride", o.cos_stride},
                {"operations_per_device", per_device}};
  const int status = report(proofs, settings, o.shard.whole() ? per_device : shard_per_device, out);
  if (partial_file) {
    Json devices_json = Json::array();
    for (const DeviceProof& p : proofs) devices_json.push_back(proof_json(p));
    Json j;
    j["kind"] = prove_kind;
    j["version"] = partial_version;
    j["commit"] = build_commit();
    j["settings"] = settings;
    j["shard"] = Json{{"index", o.shard.index}, {"count", o.shard.count}};
    j["summary"] = Json{{"devices", devices_json}};
    j["timing"] = Json{{"wall_seconds", wall}, {"cpu_seconds", process_cpu_seconds()}};
    partial_file->stream() << j.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
    partial_file->commit();
  }
  return status;
}

}  // namespace
}  // namespace tb
}  // namespace specular

int sc_main(int argc, char** argv) {
  using namespace specular;
  specular::cli::Command app{"specular_prove: every cos code x every n x every buildable device of a model, against the\n"
                             "bit-accurate core (issue 25).\n"
                             "  specular_prove --model rtl|rtl-sync|pin|tlm [--device NAME|all] [--shard I/N]\n"
                             "                 [--partial FILE] [--cos-stride K] [--quiet]\n"
                             "  specular_prove --merge FILE...",
                             "specular_prove"};
  cli::house_rules(app, "Exit status: 0 proved, 1 a difference, 2 bad usage or a refused merge, 3 internal.");
  tb::ProveOptions options;
  tb::add_prove_options(app, options);
  return cli::run(app, argc, argv, [&] {
    for (const char* other : {"--model", "--device", "--shard", "--partial", "--cos-stride"})
      if (!options.merge_files.empty() && app.count(other) > 0)
        throw tb::UsageError(std::string("--merge takes only FILE... (and --quiet), not ") + other);
    try {
      return tb::run_prove(options, app.count("--model") > 0, std::cout, std::cerr);
    } catch (const tb::UsageError&) {
      throw;  // cli::run: exit 2
    } catch (const std::exception& e) {
      std::cerr << "specular_prove: internal error: " << e.what() << '\n';
      return 3;
    }
  });
}

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}
