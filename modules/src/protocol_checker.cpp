#include "specular/protocol_checker.h"

#include <sstream>
#include <string>

namespace specular {

using sc_core::sc_time;
using sc_core::sc_time_stamp;

namespace {

// Messages are built only when something is reported: the checker is on the hot path.
void warn(const char* type, const std::string& message) {
  SC_REPORT_WARNING(type, message.c_str());
}

std::string at(const sc_time& when) { return when.to_string(); }

}  // namespace

ProtocolChecker::ProtocolChecker(sc_core::sc_module_name name) : sc_module(name) {
  SPECULAR_HAS_PROCESS(ProtocolChecker);
  SC_METHOD(on_start);
  sensitive << start.pos();
  dont_initialize();
  SC_METHOD(on_load);
  sensitive << load_n30.pos() << load_r31.pos() << load_g32.pos() << load_b33.pos();
  dont_initialize();
  SC_METHOD(on_done);
  sensitive << done35.pos();
  dont_initialize();
  SC_METHOD(on_reset);  // runs once at time 0 too: reset may be low from power-on
  sensitive << reset_n.neg();
  SC_METHOD(on_watchdog);
  sensitive << watchdog_;
  dont_initialize();
  SC_METHOD(on_clock);  // no static sensitivity: it arms itself only for a non-sc_clock
}

void ProtocolChecker::start_of_simulation() {
  clock_ = dynamic_cast<const sc_core::sc_clock*>(clk.get_interface());
  if (clock_ == nullptr) return;
  period_ = clock_->period();
  // sc_clock's first edge is at start_time(); the fall follows the rise by duty·T.
  falling_phase_ = clock_->posedge_first() ? clock_->start_time() + period_ * clock_->duty_cycle()
                                           : clock_->start_time();
}

bool ProtocolChecker::at_falling_edge(const sc_time& when) const {
  if (clock_ != nullptr) {
    if (when < falling_phase_) return false;
    return (when - falling_phase_).value() % period_.value() == 0;
  }
  return fall_seen_ && last_fall_ == when;
}

void ProtocolChecker::report_falling_edge_start(const sc_time& when) {
  std::ostringstream message;
  message << "start (pin 27) rose at " << at(when)
          << ", the same instant as a falling edge of the clock (pin 28): flip-flop 42 "
             "samples Q41 at that edge, a race (spec §3 protocol: start rises with a "
             "rising clock edge; a start exactly at a falling edge is not allowed)";
  warn(report::start_at_falling_edge, message.str());
}

void ProtocolChecker::on_start() {
  const sc_time now = sc_time_stamp();
  last_start_edge_ = now;
  start_edge_seen_ = true;
  if (!reset_n.read()) {
    std::ostringstream message;
    message << "start (pin 27) rose at " << at(now)
            << " while reset (pin 29) is low: the control unit ignores it, no operation";
    warn(report::start_during_reset, message.str());
    return;
  }
  if (!reset_seen_ && !before_reset_reported_) {
    before_reset_reported_ = true;
    std::ostringstream message;
    message << "start (pin 27) at " << at(now)
            << " before any reset since power-on: pulse pin 29 low first; a real device's "
               "control unit powers on in an unknown state (the model's flip-flops power "
               "on cleared). Reported once";
    warn(report::start_before_reset, message.str());
  }
  last_start_race_reported_ = at_falling_edge(now);
  if (last_start_race_reported_) report_falling_edge_start(now);

  // The flip-flops still hold their values from before this edge (they update later
  // in this delta cycle), so they show what the control unit was doing.
  if (q41.read() || q42.read() || !nand45.read()) {
    std::ostringstream message;
    message << "start (pin 27) at " << at(now) << " while pass 1 of the operation started at "
            << (pending_count_ > 0 ? at(newest_pending()) : std::string("(unknown)"))
            << " is pending (Q41 = " << q41.read() << ", Q42 = " << q42.read()
            << ", NAND 45 = " << nand45.read()
            << "): the control unit ignores this edge, the operation is lost (spec §3: the "
               "next start may come 2 clock periods after the previous one at the earliest)";
    warn(report::start_while_busy, message.str());
    return;
  }
  if (start_seen_ && period_ != sc_core::SC_ZERO_TIME && now - last_start_ < 2 * period_) {
    std::ostringstream message;
    message << "start (pin 27) at " << at(now) << ", " << at(now - last_start_)
            << " after the previous start: less than 2 clock periods (2 x " << at(period_)
            << "), the spec's minimum start interval (§3 protocol)";
    warn(report::start_too_soon, message.str());
  }
  start_seen_ = true;
  last_start_ = now;
  push_pending(now);
}

void ProtocolChecker::on_load() {
  const sc_time now = sc_time_stamp();
  // Legal: no operation in flight, or only one that starts at this very instant.
  if (pending_count_ == 0 || !(oldest_pending() < now)) return;
  std::ostringstream message;
  message << "register";
  const char* separator = " ";
  const std::pair<const wire_in*, const char*> strobes[] = {
      {&load_n30, "2 (n, strobe 30)"},
      {&load_r31, "10 (R, strobe 31)"},
      {&load_g32, "11 (G, strobe 32)"},
      {&load_b33, "12 (B, strobe 33)"}};
  for (const auto& [strobe, what] : strobes) {
    if (!strobe->posedge()) continue;
    message << separator << what;
    separator = ", ";
  }
  message << " written at " << at(now) << " during the operation started at "
          << at(oldest_pending())
          << ": registers 2 and 10-12 must hold from before start until 35 rises (spec §3 "
             "protocol); that operation's result mixes old and new operands";
  warn(report::load_while_busy, message.str());
}

void ProtocolChecker::on_done() {
  if (pending_count_ > 0) pop_pending();
}

void ProtocolChecker::on_reset() {
  if (reset_n.read()) return;  // the initial run, with reset high
  reset_seen_ = true;
  if (pending_count_ == 0) return;
  std::ostringstream message;
  message << "reset (pin 29) at " << at(sc_time_stamp()) << " while " << pending_count_
          << " operation(s) are in flight (oldest started at " << at(oldest_pending())
          << "): the control unit returns to idle and they produce no result";
  warn(report::reset_mid_operation, message.str());
  pending_count_ = 0;
}

void ProtocolChecker::on_clock() {
  if (clock_ != nullptr) return;  // edges are computed from the sc_clock; never run again
  next_trigger(clk.value_changed_event());
  if (!clock_watch_started_) {  // the initial run: not an edge
    clock_watch_started_ = true;
    return;
  }
  const sc_time now = sc_time_stamp();
  if (clk.read()) {
    // The shortest interval between rises: a clock that pauses between operations (the
    // TLM transactor's on-demand pin 28) keeps its period across the pause.
    if (rise_seen_ && now > last_rise_ &&
        (period_ == sc_core::SC_ZERO_TIME || now - last_rise_ < period_))
      period_ = now - last_rise_;
    last_rise_ = now;
    rise_seen_ = true;
    return;
  }
  last_fall_ = now;
  fall_seen_ = true;
  // The start may have come earlier in this same instant (another delta cycle).
  if (start_edge_seen_ && last_start_edge_ == now && !last_start_race_reported_) {
    last_start_race_reported_ = true;
    report_falling_edge_start(now);
  }
}

sc_time ProtocolChecker::deadline() const {
  // An operation takes 2.5 T from a start on a rising edge, up to 3 T at another phase.
  return period_ != sc_core::SC_ZERO_TIME ? 4 * period_ : no_clock_timeout_;
}

void ProtocolChecker::push_pending(const sc_time& when) {
  if (pending_count_ == pending_capacity) pop_pending();  // the watchdog reported it
  pending_[(pending_head_ + pending_count_) % pending_capacity] = when;
  ++pending_count_;
  if (!watchdog_armed_) arm_watchdog();
}

void ProtocolChecker::pop_pending() {
  pending_head_ = (pending_head_ + 1) % pending_capacity;
  --pending_count_;
}

void ProtocolChecker::arm_watchdog() {
  watchdog_armed_ = pending_count_ > 0;
  if (!watchdog_armed_) return;
  const sc_time due = oldest_pending() + deadline();
  const sc_time now = sc_time_stamp();
  watchdog_.notify(due > now ? due - now : sc_core::SC_ZERO_TIME);
}

void ProtocolChecker::on_watchdog() {
  const sc_time now = sc_time_stamp();
  if (pending_count_ > 0 && oldest_pending() + deadline() <= now) {
    const sc_time started = oldest_pending();
    const bool clock_moved =
        clock_ != nullptr || (rise_seen_ && last_rise_ > started) || (fall_seen_ && last_fall_ > started);
    std::ostringstream message;
    if (clock_moved) {
      message << "the operation started at " << at(started) << " has not finished by " << at(now)
              << " (4 clock periods) although pin 28 had clock edges since: 35 never rose. "
                 "The clock stopped or slowed, or the control unit is locked; pulse reset "
                 "(pin 29)";
      warn(report::no_done, message.str());
    } else {
      message << "the operation started at " << at(started) << " has seen no clock edge on pin 28 by "
              << at(now) << ": it cannot advance; drive the reference clock";
      warn(report::no_clock, message.str());
    }
    pop_pending();
  }
  arm_watchdog();
}

}  // namespace specular
