/// \file
/// Protocol checker: watches the device's pins and control unit 16, reports misuse.
#pragma once

#include <array>
#include <cstddef>

#include "specular/report_ids.h"
#include "specular/systemc.h"

namespace specular {

/// Watches pins 27–33 and 35 and flip-flops 41, 42 / NAND 45 of control unit 16 and
/// reports each breach of spec §3 "protocol" as an SC_REPORT_WARNING whose message
/// type is one of report_ids.h. The device itself behaves as its gates do; the
/// checker only observes. Raise the types to errors or silence them with
/// `sc_core::sc_report_handler::set_actions(type, …)` (see report_ids.h and
/// docs/misuse.md).
///
/// The rules, with a start edge at t0 on a rising clock edge and period T (spec timing
/// table: Q41 at t0, Q42 at t0+T/2, pass 1 at t0+T, Q43 at t0+3T/2, pass 2 at t0+2T,
/// 35↑ at t0+5T/2):
/// \code{.unparsed}
///   start-while-busy   start while Q41 or Q42 is set or AND 40 holds 41 in reset
///                      (t0 < t < t0+3T/2): the edge is lost or merged.
///   start-too-soon     start accepted but less than 2 T after the previous start
///                      (t0+3T/2 < t < t0+2T): breaks the minimum interval. A start
///                      at t0+2T while the previous operation finishes is legal.
///   start-at-falling-edge  start at the same instant as a falling clock edge (race).
///   start-during-reset start while pin 29 is low (ignored by the control unit).
///   start-before-reset start before pin 29 was ever low since power-on (once).
///   load-while-busy    strobe 30–33 rises while an operation that started earlier
///                      has not reached 35↑ (n or R, G, B changed mid-operation).
///                      Strobes at the start instant itself, or after 35↑, are legal:
///                      the pipelined protocol reloads a quarter period before a
///                      start and only after 35 rose.
///   reset-mid-operation pin 29 falls while an operation is in flight (aborted).
///   no-clock           an operation started and pin 28 had no edge for 4 T (or
///                      `no_clock_timeout` while no period is known yet).
///   no-done            pin 28 had edges after a start, but 35 did not rise within
///                      4 T: the clock stopped or slowed mid-operation, or the
///                      control unit is locked, until the next reset.
/// \endcode
///
/// Cost: a handful of process activations per operation (start, done, strobes, one
/// timed watchdog). When pin 28 is bound to an sc_clock, its edges are computed from
/// the clock's period and phase and the checker is not sensitive to it at all;
/// otherwise it watches pin 28's edges to measure the period.
class ProtocolChecker : public sc_core::sc_module {
 public:
  wire_in start{"start"};        ///< pin 27
  wire_in clk{"clk"};            ///< pin 28
  wire_in reset_n{"reset_n"};    ///< pin 29
  wire_in load_n30{"load_n30"};  ///< pin 30: write register 2 (n)
  wire_in load_r31{"load_r31"};  ///< pin 31: write register 10 (R)
  wire_in load_g32{"load_g32"};  ///< pin 32: write register 11 (G)
  wire_in load_b33{"load_b33"};  ///< pin 33: write register 12 (B)
  wire_in done35{"done35"};      ///< pin 35
  wire_in q41{"q41"};            ///< control unit 16: flip-flop 41 (start latched)
  wire_in q42{"q42"};            ///< control unit 16: flip-flop 42 (pass 1 pending)
  wire_in nand45{"nand45"};      ///< control unit 16: NAND 45 (low: pass 1 write, 41 held reset)

  /// Registers the checker's processes; bind every port above (DevicePins::bind does).
  explicit ProtocolChecker(sc_core::sc_module_name name);

  /// How long a start may wait for a clock edge before `no-clock` is reported, while
  /// the clock period is unknown (pin 28 not an sc_clock and not yet toggled twice).
  void set_no_clock_timeout(const sc_core::sc_time& timeout) { no_clock_timeout_ = timeout; }
  /// Operations started (accepted by the control unit) and not yet done.
  std::size_t in_flight() const { return pending_count_; }

 private:
  void start_of_simulation() override;
  void on_start();
  void on_load();
  void on_done();
  void on_reset();
  void on_clock();     // only when pin 28 is not an sc_clock
  void on_watchdog();  // no-clock / no-done

  bool at_falling_edge(const sc_core::sc_time& when) const;
  void push_pending(const sc_core::sc_time& when);
  void pop_pending();
  const sc_core::sc_time& oldest_pending() const { return pending_[pending_head_]; }
  const sc_core::sc_time& newest_pending() const {
    return pending_[(pending_head_ + pending_count_ - 1) % pending_capacity];
  }
  sc_core::sc_time deadline() const;
  void arm_watchdog();
  void report_falling_edge_start(const sc_core::sc_time& when);

  // Clock knowledge: from the sc_clock (exact) or measured from pin 28's edges (the
  // shortest interval between rises, so that a clock may pause between operations).
  const sc_core::sc_clock* clock_ = nullptr;
  sc_core::sc_time period_ = sc_core::SC_ZERO_TIME;     ///< zero: not known yet
  sc_core::sc_time falling_phase_ = sc_core::SC_ZERO_TIME;  ///< sc_clock: offset of falls
  sc_core::sc_time last_rise_ = sc_core::SC_ZERO_TIME;
  sc_core::sc_time last_fall_ = sc_core::SC_ZERO_TIME;
  bool rise_seen_ = false;
  bool fall_seen_ = false;
  bool clock_watch_started_ = false;
  sc_core::sc_time no_clock_timeout_{1, sc_core::SC_US};

  // Starts.
  bool reset_seen_ = false;
  bool before_reset_reported_ = false;
  bool start_seen_ = false;                              ///< an accepted start
  sc_core::sc_time last_start_ = sc_core::SC_ZERO_TIME;  ///< the last accepted start
  bool start_edge_seen_ = false;                         ///< any start edge
  sc_core::sc_time last_start_edge_ = sc_core::SC_ZERO_TIME;
  bool last_start_race_reported_ = false;

  // Operations accepted by the control unit and not yet at 35↑, oldest first.
  static constexpr std::size_t pending_capacity = 8;
  std::array<sc_core::sc_time, pending_capacity> pending_{};
  std::size_t pending_head_ = 0;
  std::size_t pending_count_ = 0;
  sc_core::sc_event watchdog_;
  bool watchdog_armed_ = false;
};

}  // namespace specular
