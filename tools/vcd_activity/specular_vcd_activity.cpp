// specular_vcd_activity MAP VCD OUT: the toggle counter of scripts/flows/energy/energy.py
// (issue 36, docs/energy.md) for VCDs of hundreds of MB, where the Python reader spends
// as long as the gate-level replay that wrote them. The same rules as energy.py's
// read_vcd, which stays the reference (tests/silicon_energy_counter compares the two):
//   - a net toggles when its value at the end of a time step differs from the previous
//     step's, 0 <-> 1 only (x and z are no toggles; a change and its return inside one
//     step, a zero-delay race, is none);
//   - a ROM macro reads when an address net of its group moves, once per access time;
//   - a result is a rising (falling) edge of the strobe, or a rising clock edge with the
//     strobe high (clk_valid; the result held at the end of the replay counts too);
//   - every toggle adds its net's energy per rise or fall, every read its macro's energy
//     per read, and each result records the running energy (the convergence).
//
// MAP (written by energy.py compute), tab-separated lines:
//   nets N                      global nets 0..N-1
//   weight NET RISE_PJ FALL_PJ  a net's energy per rise and per fall
//   sig SCOPE BIT NET           the VCD's (scope path, bit name) of a global net
//   group NAME ENERGY_PJ ACCESS_PS NET,NET,...   a ROM macro's address nets
//   strobe NET rise|fall|clk_valid    clock NET    begin PS
// OUT, tab-separated: toggles NET RISES FALLS (nets that toggled), reads NAME COUNT,
//   checkpoint T_PS RESULTS ENERGY_PJ (one per result), end T_PS TIMESCALE_PS.
// Exit status: 0 written, 1 a file unreadable or malformed (named with the line), 2 usage.
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "cli.h"

namespace {

struct Target {
    int net;
    int position;  // the character of a vector's value; -1: a scalar (its last character)
};

struct Group {
    std::string name;
    double energy_pj = 0.0;
    double access_ps = 0.0;
    double last_read_ps = -1e30;
    long long reads = 0;
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "specular_vcd_activity: " << message << "\n";
    std::exit(1);
}

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, separator)) fields.push_back(field);
    return fields;
}

std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    std::string w;
    while (in >> w) fields.push_back(w);
    return fields;
}

bool binary(char v) { return v == '0' || v == '1'; }

enum class ResultMode { none, rise, fall, clk_valid };  // how a result shows (the map's strobe line)

/// The counts of `vcd_path` by the rules of `map_path`, written to `out_path`.
int count_activity(const std::string& map_path, const std::string& vcd_path, const std::string& out_path) {
    // ---- the map ------------------------------------------------------------------
    std::ifstream map_in(map_path);
    if (!map_in) fail(std::string("cannot read the map '") + map_path + "'");
    int net_count = -1;
    std::vector<double> rise_pj, fall_pj;
    std::unordered_map<std::string, int> wanted;  // scope + '\t' + bit -> net
    std::vector<Group> groups;
    std::vector<std::vector<int>> net_groups;
    int strobe = -1, clock = -1;
    ResultMode mode = ResultMode::none;
    double begin_ps = 0.0;
    std::string line;
    for (int number = 1; std::getline(map_in, line); ++number) {
        const auto f = split(line, '\t');
        const auto where = std::string(map_path) + ":" + std::to_string(number);
        auto net_of = [&](const std::string& text) {
            const int net = std::atoi(text.c_str());
            if (net < 0 || net >= net_count) fail(where + ": net '" + text + "' is not in 0.." + std::to_string(net_count - 1));
            return net;
        };
        if (f.size() == 2 && f[0] == "nets") {
            net_count = std::atoi(f[1].c_str());
            rise_pj.assign(net_count, 0.0);
            fall_pj.assign(net_count, 0.0);
            net_groups.assign(net_count, {});
        } else if (net_count < 0) {
            fail(where + ": the map must begin with 'nets N'");
        } else if (f.size() == 4 && f[0] == "weight") {
            const int net = net_of(f[1]);
            rise_pj[net] = std::strtod(f[2].c_str(), nullptr);
            fall_pj[net] = std::strtod(f[3].c_str(), nullptr);
        } else if (f.size() == 4 && f[0] == "sig") {
            wanted[f[1] + '\t' + f[2]] = net_of(f[3]);
        } else if (f.size() == 5 && f[0] == "group") {
            Group g;
            g.name = f[1];
            g.energy_pj = std::strtod(f[2].c_str(), nullptr);
            g.access_ps = std::strtod(f[3].c_str(), nullptr);
            for (const auto& n : split(f[4], ',')) net_groups[net_of(n)].push_back(static_cast<int>(groups.size()));
            groups.push_back(g);
        } else if (f.size() == 3 && f[0] == "strobe") {
            strobe = net_of(f[1]);
            mode = f[2] == "rise" ? ResultMode::rise : f[2] == "fall" ? ResultMode::fall
                 : f[2] == "clk_valid" ? ResultMode::clk_valid : ResultMode::none;
            if (mode == ResultMode::none) fail(where + ": mode '" + f[2] + "' is not rise, fall or clk_valid");
        } else if (f.size() == 2 && f[0] == "clock") {
            clock = net_of(f[1]);
        } else if (f.size() == 2 && f[0] == "begin") {
            begin_ps = std::strtod(f[1].c_str(), nullptr);
        } else if (!line.empty()) {
            fail(where + ": '" + line + "' is no map line");
        }
    }
    if (net_count < 0) fail(std::string("the map '") + map_path + "' names no nets");

    // ---- the VCD's header: which identifier carries which nets ----------------------
    std::ifstream vcd(vcd_path);
    if (!vcd) fail(std::string("cannot read the VCD '") + vcd_path + "'");
    std::unordered_map<std::string, int> id_index;  // VCD identifier -> slot
    std::vector<std::vector<Target>> targets;
    std::vector<std::size_t> widths;
    std::vector<std::string> scope;
    double timescale_ps = 1.0;
    const std::regex timescale_re(R"(\s*(\d+)\s*([munpf]?s))");
    const std::regex range_re(R"(\[(\d+):(\d+)\])");
    bool definitions_ended = false;
    while (std::getline(vcd, line)) {
        auto s = words(line);
        if (s.empty()) continue;
        if (s[0] == "$timescale") {
            std::string text;
            for (std::size_t k = 1; k < s.size(); ++k) text += (k > 1 ? " " : "") + s[k];
            while (text.find("$end") == std::string::npos && std::getline(vcd, line)) text += " " + line;
            std::smatch m;
            if (!std::regex_search(text, m, timescale_re)) fail("a $timescale without a unit: '" + text + "'");
            const std::string unit = m[2];
            const double scale = unit == "s" ? 1e12 : unit == "ms" ? 1e9 : unit == "us" ? 1e6 : unit == "ns" ? 1e3
                               : unit == "ps" ? 1.0 : 1e-3;
            timescale_ps = std::stoi(m[1]) * scale;
        } else if (s[0] == "$scope" && s.size() > 2) {
            scope.push_back(s[2]);
        } else if (s[0] == "$upscope") {
            if (!scope.empty()) scope.pop_back();
        } else if (s[0] == "$var" && s.size() > 4) {
            const std::size_t width = std::stoul(s[2]);
            const std::string& id = s[3];
            std::string name = s[4];
            const bool has_range = s.size() > 5 && s[5].rfind("[", 0) == 0;
            std::string base;
            for (std::size_t k = 0; k < scope.size(); ++k) base += (k ? "." : "") + scope[k];
            if (!name.empty() && name[0] == '\\') name.erase(0, 1);
            std::vector<Target> found;
            if (!has_range || width == 1) {
                const auto it = wanted.find(base + '\t' + (has_range ? name + s[5] : name));
                if (it != wanted.end()) found.push_back({it->second, -1});
            } else {
                std::smatch m;
                if (!std::regex_match(s[5], m, range_re)) fail("a $var range that is not [hi:lo]: '" + line + "'");
                const int hi = std::stoi(m[1]), lo = std::stoi(m[2]);
                const int step = hi >= lo ? -1 : 1;
                int position = 0;
                for (int k = hi; k != lo + step; k += step, ++position) {
                    const auto it = wanted.find(base + '\t' + name + "[" + std::to_string(k) + "]");
                    if (it != wanted.end()) found.push_back({it->second, position});
                }
            }
            if (!found.empty()) {
                auto [it, inserted] = id_index.try_emplace(id, static_cast<int>(targets.size()));
                if (inserted) {
                    targets.emplace_back();
                    widths.push_back(width);
                }
                auto& t = targets[it->second];
                t.insert(t.end(), found.begin(), found.end());
                widths[it->second] = width;
            }
        } else if (s[0] == "$enddefinitions") {
            definitions_ended = true;
            break;
        }
    }
    if (!definitions_ended) fail(std::string("'") + vcd_path + "' has no $enddefinitions: not a VCD");

    // ---- the value changes, one time step at a time ---------------------------------
    std::vector<char> value(net_count, 'x');
    std::vector<long long> rises(net_count, 0), falls(net_count, 0);
    std::vector<std::string> pending_value(targets.size());
    std::vector<char> is_pending(targets.size(), 0);
    std::vector<int> pending;  // slots in the order they first changed in this step
    std::vector<char> group_moved(groups.size(), 0);
    std::vector<int> moved;
    double energy = 0.0;
    long long results = 0;
    std::vector<std::tuple<double, long long, double>> checkpoints;
    double t_ps = 0.0;
    char clock_value = 'x', strobe_value = 'x';

    auto flush = [&]() {
        const bool counting = t_ps >= begin_ps;
        char new_clock = clock_value, new_strobe = strobe_value;
        for (const int slot : pending) {
            const std::string& raw = pending_value[slot];
            for (const auto& [net, position] : targets[slot]) {
                const char v = position < 0 ? raw.back()
                             : static_cast<std::size_t>(position) < raw.size() ? raw[position] : '0';
                const char old = value[net];
                if (v == old) continue;
                value[net] = v;
                if (net == clock) new_clock = v;
                if (net == strobe) new_strobe = v;
                if (!counting || !binary(old) || !binary(v)) continue;
                if (v == '1') {
                    ++rises[net];
                    energy += rise_pj[net];
                } else {
                    ++falls[net];
                    energy += fall_pj[net];
                }
                for (const int g : net_groups[net]) {
                    if (!group_moved[g]) {
                        group_moved[g] = 1;
                        moved.push_back(g);
                    }
                }
            }
            is_pending[slot] = 0;
        }
        // one read per address transition; transitions within one access time of the read
        // they follow are merged into it (the macro's address-transition detector)
        for (const int g : moved) {
            auto& group = groups[g];
            if (counting && t_ps - group.last_read_ps >= group.access_ps) {
                ++group.reads;
                group.last_read_ps = t_ps;
                energy += group.energy_pj;
            }
            group_moved[g] = 0;
        }
        moved.clear();
        if (counting) {
            const bool result = (mode == ResultMode::rise && strobe_value == '0' && new_strobe == '1') ||
                                (mode == ResultMode::fall && strobe_value == '1' && new_strobe == '0') ||
                                (mode == ResultMode::clk_valid && clock_value == '0' && new_clock == '1' &&
                                 strobe_value == '1');
            if (result) checkpoints.emplace_back(t_ps, ++results, energy);
        }
        clock_value = new_clock;
        strobe_value = new_strobe;
        pending.clear();
    };
    auto set_pending = [&](int slot, std::string&& v) {
        if (!is_pending[slot]) {
            is_pending[slot] = 1;
            pending.push_back(slot);
        }
        pending_value[slot] = std::move(v);
    };
    while (std::getline(vcd, line)) {
        if (line.empty()) continue;
        const char c = line[0];
        if (c == '#') {
            if (!pending.empty()) flush();
            t_ps = static_cast<double>(std::strtoll(line.c_str() + 1, nullptr, 10)) * timescale_ps;
        } else if (c == '0' || c == '1' || c == 'x' || c == 'z' || c == 'X' || c == 'Z') {
            std::size_t b = 1, e = line.size();
            while (b < e && std::isspace(static_cast<unsigned char>(line[b]))) ++b;
            while (e > b && std::isspace(static_cast<unsigned char>(line[e - 1]))) --e;
            const auto it = id_index.find(line.substr(b, e - b));
            if (it != id_index.end()) set_pending(it->second, std::string(1, static_cast<char>(std::tolower(c))));
        } else if (c == 'b' || c == 'B') {
            const auto space = line.find(' ');
            if (space == std::string::npos) continue;
            std::size_t b = space + 1, e = line.size();
            while (b < e && std::isspace(static_cast<unsigned char>(line[b]))) ++b;
            while (e > b && std::isspace(static_cast<unsigned char>(line[e - 1]))) --e;
            const auto it = id_index.find(line.substr(b, e - b));
            if (it == id_index.end()) continue;
            std::string v = line.substr(1, space - 1);
            for (auto& ch : v) ch = static_cast<char>(std::tolower(ch));
            const std::size_t width = widths[it->second];
            if (!v.empty() && v.size() < width) {  // leading zeros (or x, z) left out
                const char pad = (v[0] == 'x' || v[0] == 'z') ? v[0] : '0';
                v.insert(0, width - v.size(), pad);
            }
            set_pending(it->second, std::move(v));
        }
    }
    if (!pending.empty()) flush();
    if (mode == ResultMode::clk_valid && strobe_value == '1' && t_ps >= begin_ps) checkpoints.emplace_back(t_ps, ++results, energy);

    // ---- the counts -------------------------------------------------------------------
    FILE* out = std::fopen(out_path.c_str(), "w");
    if (!out) fail(std::string("cannot write '") + out_path + "'");
    for (int net = 0; net < net_count; ++net)
        if (rises[net] || falls[net]) std::fprintf(out, "toggles\t%d\t%lld\t%lld\n", net, rises[net], falls[net]);
    for (const auto& g : groups) std::fprintf(out, "reads\t%s\t%lld\n", g.name.c_str(), g.reads);
    for (const auto& [t, r, e] : checkpoints) std::fprintf(out, "checkpoint\t%.17g\t%lld\t%.17g\n", t, r, e);
    std::fprintf(out, "end\t%.17g\t%.17g\n", t_ps, timescale_ps);
    return std::fclose(out) == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    specular::cli::Command app{"The toggle counter of scripts/flows/energy/energy.py for large VCDs (docs/energy.md).",
                               "specular_vcd_activity"};
    specular::cli::house_rules(app, "Exit status: 0 written, 1 a file unreadable or malformed (named with "
                                    "the line), 2 usage.");
    std::string map_path, vcd_path, out_path;
    app.add_option("MAP", map_path, "the map energy.py compute writes")->required();
    app.add_option("VCD", vcd_path, "the gate-level replay's VCD")->required();
    app.add_option("OUT", out_path, "the counts, tab-separated")->required();
    return specular::cli::run(app, argc, argv, [&] { return count_activity(map_path, vcd_path, out_path); });
}
