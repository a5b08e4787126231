#include "partial_set.h"

#include <sys/resource.h>
#include <unistd.h>

#include <fstream>

#include "git_commit.h"  // generated at build time (tools/run_support/CMakeLists.txt)
#include "usage_error.h"

namespace specular {
namespace tb {

const char* build_commit() { return SPECULAR_GIT_COMMIT; }

double process_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

namespace {

PartialFile read_partial(const std::string& path, const std::string& kind) {
  std::ifstream in(path);
  if (!in) throw UsageError("--merge: cannot read '" + path + "'");
  PartialFile p;
  p.path = path;
  try {
    p.json = Json::parse(in);
  } catch (const std::exception& e) {
    throw UsageError("--merge: '" + path + "' is not JSON: " + e.what());
  }
  try {
    if (!p.json.is_object() || p.json.value("kind", "") != kind)
      throw UsageError("--merge: '" + path + "' is not a " + kind + " (its kind: " +
                       (p.json.is_object() && p.json.contains("kind") ? dump_json(p.json["kind"]) : "none") + ")");
    if (p.json.at("version").get<int>() != partial_version)
      throw UsageError("--merge: '" + path + "' is a version " + p.json.at("version").dump() +
                       " partial; this specular_tb reads version " + std::to_string(partial_version));
    p.shard.index = p.json.at("shard").at("index").get<std::size_t>();
    p.shard.count = p.json.at("shard").at("count").get<std::size_t>();
    if (p.shard.count < 1 || p.shard.index >= p.shard.count)
      throw UsageError("--merge: '" + path + "' names shard " + p.shard.text() + ", not I/N with I < N");
    p.json.at("settings");
    p.json.at("commit").get<std::string>();
    p.json.at("summary");
  } catch (const UsageError&) {
    throw;
  } catch (const std::exception& e) {
    throw UsageError("--merge: '" + path + "' is not a complete partial result: " + e.what());
  }
  return p;
}

/// The first key whose value differs, as "key: a vs b".
std::string first_difference(const Json& a, const Json& b) {
  for (const auto& [key, value] : a.items())
    if (!b.contains(key) || b.at(key) != value)
      return key + " " + dump_json(value) + " vs " + (b.contains(key) ? dump_json(b.at(key)) : "(none)");
  for (const auto& [key, value] : b.items())
    if (!a.contains(key)) return key + " (none) vs " + dump_json(value);
  return "?";
}

/// Equal as JSON values, whatever the order of the keys (a file rewritten by another
/// tool may sort them).
bool same_content(const Json& a, const Json& b) {
  return nlohmann::json::parse(dump_json(a)) == nlohmann::json::parse(dump_json(b));
}

}  // namespace

std::vector<PartialFile> read_complete_set(const std::vector<std::string>& files,
                                          const std::string& kind) {
  if (files.empty()) throw UsageError("--merge needs the partial files of every shard (FILE...)");
  std::vector<PartialFile> parts;
  for (const std::string& f : files) parts.push_back(read_partial(f, kind));
  const PartialFile& first = parts.front();
  const std::size_t count = first.shard.count;
  std::vector<const PartialFile*> by_index(count, nullptr);
  for (const PartialFile& p : parts) {
    if (p.json.at("commit") != first.json.at("commit"))
      throw UsageError("--merge: '" + p.path + "' comes from commit " + p.json.at("commit").get<std::string>() +
                       ", '" + first.path + "' from " + first.json.at("commit").get<std::string>() +
                       ": shards of one run come from one build");
    if (!same_content(p.json.at("settings"), first.json.at("settings")))
      throw UsageError("--merge: '" + p.path + "' has other settings than '" + first.path +
                       "' (" + first_difference(p.json.at("settings"), first.json.at("settings")) + ")");
    if (p.shard.count != count)
      throw UsageError("--merge: '" + p.path + "' is shard " + p.shard.text() + " of " +
                       std::to_string(p.shard.count) + ", '" + first.path + "' one of " +
                       std::to_string(count) + " shards");
    if (by_index[p.shard.index] != nullptr)
      throw UsageError("--merge: shard " + p.shard.text() + " is given twice: '" +
                       by_index[p.shard.index]->path + "' and '" + p.path + "'");
    by_index[p.shard.index] = &p;
  }
  std::string missing;
  std::size_t missing_count = 0;
  for (std::size_t i = 0; i < count; ++i)
    if (by_index[i] == nullptr) {
      if (++missing_count <= 10) missing += (missing.empty() ? "" : ", ") + Shard{i, count}.text();
    }
  if (missing_count > 0)
    throw UsageError("--merge: " + std::to_string(missing_count) + " of " + std::to_string(count) +
                     " shards missing: " + missing + (missing_count > 10 ? ", ..." : ""));

  std::vector<PartialFile> ordered;
  for (const PartialFile* p : by_index) ordered.push_back(*p);
  return ordered;
}

}  // namespace tb
}  // namespace specular
