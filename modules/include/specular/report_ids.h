/// \file
/// The sc_report message types the model issues, in one place.
///
/// Every misuse the model notices is reported through SystemC's report handler with
/// one of these message types, so a user can filter it or make it fatal:
/// \code
///   // stop the simulation (throw sc_report) on any protocol misuse:
///   sc_core::sc_report_handler::set_actions(specular::report::start_while_busy,
///                                           sc_core::SC_THROW);
///   // or on all of them at once (the types share the prefix):
///   for (const char* type : specular::report::protocol_types)
///     sc_core::sc_report_handler::set_actions(type, sc_core::SC_DISPLAY | sc_core::SC_THROW);
///   // silence one:
///   sc_core::sc_report_handler::set_actions(specular::report::reset_mid_operation,
///                                           sc_core::SC_DO_NOTHING);
/// \endcode
/// SpecularTarget reports its first refusal of each kind as tlm_access_refused.
/// docs/misuse.md lists, for each type, the misuse, the spec rule it breaks and what
/// the device does with it.
#pragma once

namespace specular {
/// The sc_report message types the model issues (see report_ids.h, docs/misuse.md).
namespace report {

// ---- pin protocol (ProtocolChecker, inside SpecularDevice; spec §3 "protocol") ----

/// Start (pin 27) while pass 1 of the previous operation is pending: the control unit
/// ignores the edge (flip-flop 41 is already set, or held in reset by AND 40), so
/// the operation is lost.
inline constexpr const char start_while_busy[] = "/specular/protocol/start-while-busy";
/// Start accepted, but less than 2 clock periods after the previous start (the
/// spec's minimum start interval).
inline constexpr const char start_too_soon[] = "/specular/protocol/start-too-soon";
/// Start exactly at a falling clock edge: flip-flop 42 samples Q41 at that edge, a race.
inline constexpr const char start_at_falling_edge[] = "/specular/protocol/start-at-falling-edge";
/// Start while reset (pin 29) is asserted: the control unit ignores it.
inline constexpr const char start_during_reset[] = "/specular/protocol/start-during-reset";
/// Start before pin 29 was ever asserted since power-on: a real device's flip-flops
/// power on in an unknown state (the model's power on cleared).
inline constexpr const char start_before_reset[] = "/specular/protocol/start-before-reset";
/// Register 2 or 10–12 written (strobe 30–33) while an operation that started
/// earlier has not reached the rising edge of 35: that operation's result mixes
/// old and new operands.
inline constexpr const char load_while_busy[] = "/specular/protocol/load-while-busy";
/// Reset asserted while an operation is in flight: it is abandoned, no result.
inline constexpr const char reset_mid_operation[] = "/specular/protocol/reset-mid-operation";
/// Start, and no clock edge on pin 28 within the checker's timeout: the operation
/// cannot advance.
inline constexpr const char no_clock[] = "/specular/protocol/no-clock";
/// Pin 28 had edges after a start, but 35 did not rise within 4 clock periods: the
/// clock stopped or slowed mid-operation, or the control unit is locked (until reset).
inline constexpr const char no_done[] = "/specular/protocol/no-done";

/// Every protocol type above, for set_actions loops.
inline constexpr const char* protocol_types[] = {
    start_while_busy,  start_too_soon,   start_at_falling_edge, start_during_reset,
    start_before_reset, load_while_busy, reset_mid_operation,   no_clock,
    no_done};

// ---- TLM target (SpecularTarget, every implementation) ------------------------------

/// A bus access refused (STATUS.error set): the first refusal of each cause per target
/// is reported, naming the payload field or register, its value and the rule it
/// breaks; later ones only set STATUS and ERROR_ADDRESS.
inline constexpr const char tlm_access_refused[] = "/specular/tlm/access-refused";

}  // namespace report
}  // namespace specular
