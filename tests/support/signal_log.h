// A logic-analyser for tests: records every change of a set of wires, delta cycles
// included, so that a test sees glitches and counts edges exactly.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "specular/systemc.h"

namespace specular {
namespace testing_support {

class SignalLog : public sc_core::sc_module {
 public:
  struct Change {
    std::string signal;
    sc_core::sc_time time;
    bool value;
  };
  using Watched = std::vector<std::pair<std::string, const sc_core::sc_signal_in_if<bool>*>>;

  SignalLog(sc_core::sc_module_name name, Watched watched)
      : sc_module(name), watched_(std::move(watched)), last_(watched_.size(), false) {
    SPECULAR_HAS_PROCESS(SignalLog);
    SC_METHOD(on_change);
    for (const auto& w : watched_) sensitive << w.second->value_changed_event();
    dont_initialize();
  }

  const std::vector<Change>& changes() const { return changes_; }

  /// Times at which `signal` went to `value` (rising edges for true), in order.
  std::vector<sc_core::sc_time> edges(const std::string& signal, bool value) const {
    std::vector<sc_core::sc_time> times;
    for (const Change& c : changes_)
      if (c.signal == signal && c.value == value) times.push_back(c.time);
    return times;
  }
  std::vector<sc_core::sc_time> rises(const std::string& signal) const { return edges(signal, true); }
  std::vector<sc_core::sc_time> falls(const std::string& signal) const { return edges(signal, false); }

 private:
  void start_of_simulation() override {
    for (std::size_t i = 0; i < watched_.size(); ++i) last_[i] = watched_[i].second->read();
  }
  void on_change() {
    for (std::size_t i = 0; i < watched_.size(); ++i) {
      const bool now = watched_[i].second->read();
      if (now != last_[i]) {
        changes_.push_back({watched_[i].first, sc_core::sc_time_stamp(), now});
        last_[i] = now;
      }
    }
  }

  Watched watched_;
  std::vector<bool> last_;
  std::vector<Change> changes_;
};

}  // namespace testing_support
}  // namespace specular
