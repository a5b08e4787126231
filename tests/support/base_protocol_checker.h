// A TLM-2.0 base-protocol checker for the tests: a passthrough module between an
// initiator and a target that forwards b_transport, nb_transport_fw/bw and
// transport_dbg unchanged and records every breach of IEEE 1666-2011's base protocol
// it can see (§14 generic payload, §15 phases) — on either side. The project had no
// TLM checker of its own (protocol_checker.h checks the device's pins).
//
// Checked:
//   - generic payload on entry: data pointer set, length > 0, streaming width > 0,
//     byte-enable length > 0 when a byte-enable pointer is set, response status
//     TLM_INCOMPLETE_RESPONSE, a transaction not already in flight;
//   - the target leaves command, address, data pointer, length, byte enables and
//     streaming width alone, and sets the response status before it completes;
//   - b_transport never moves the initiator's time backwards (sc_time_stamp() +
//     delay on return ≥ on entry);
//   - phases: BEGIN_REQ → [END_REQ] → BEGIN_RESP → [END_RESP], through forward and
//     backward calls and TLM_UPDATED / TLM_COMPLETED returns, with the phase a
//     return may carry; request exclusion (no BEGIN_REQ while a request is open)
//     and response exclusion (no BEGIN_RESP while a response is open);
//   - transport_dbg returns at most the length asked for.
#pragma once

#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include "functional_coverage.h"
#include "specular/systemc.h"

namespace specular {
namespace tlm_testing {

class BaseProtocolChecker : public sc_core::sc_module {
 public:
  explicit BaseProtocolChecker(sc_core::sc_module_name name) : sc_module(name) {
    target_socket.register_b_transport(this, &BaseProtocolChecker::b_transport);
    target_socket.register_nb_transport_fw(this, &BaseProtocolChecker::nb_transport_fw);
    target_socket.register_transport_dbg(this, &BaseProtocolChecker::transport_dbg);
    initiator_socket.register_nb_transport_bw(this, &BaseProtocolChecker::nb_transport_bw);
  }

  tlm_utils::simple_target_socket<BaseProtocolChecker, 32> target_socket{"target_socket"};
  tlm_utils::simple_initiator_socket<BaseProtocolChecker, 32> initiator_socket{"initiator_socket"};

  std::vector<std::string> violations;  ///< one line per breach, in the order seen
  long b_calls = 0, nb_calls = 0, dbg_calls = 0;
  long nb_completed = 0;  ///< nb transactions seen through to their end
  /// False: accesses pass unrecorded by the functional coverage (a test's own set-up
  /// and state snapshots, which are not the stimulus it is about).
  bool record_coverage = true;

  /// True when no nb transaction is left half way (call at the end of a test).
  bool idle() const { return in_flight_.empty(); }

 private:
  enum class State { request, end_request, response };
  struct Snapshot {
    tlm::tlm_command command;
    std::uint64_t address;
    unsigned char* data;
    unsigned length;
    unsigned char* enables;
    unsigned enables_length;
    unsigned streaming_width;
  };
  struct Flight {
    State state;
    Snapshot snapshot;
  };

  static Snapshot snapshot_of(const tlm::tlm_generic_payload& tx) {
    return {tx.get_command(),          tx.get_address(),           tx.get_data_ptr(),
            tx.get_data_length(),      tx.get_byte_enable_ptr(),   tx.get_byte_enable_length(),
            tx.get_streaming_width()};
  }

  void breach(const tlm::tlm_generic_payload& tx, const std::string& what) {
    std::ostringstream line;
    line << sc_core::sc_time_stamp() << " address 0x" << std::hex << tx.get_address() << ": "
         << what;
    violations.push_back(line.str());
  }

  void check_entry(const tlm::tlm_generic_payload& tx, const char* call) {
    const std::string where = std::string(call) + ": ";
    if (tx.get_data_ptr() == nullptr) breach(tx, where + "data pointer is null");
    if (tx.get_data_length() == 0) breach(tx, where + "data length is 0");
    if (tx.get_streaming_width() == 0) breach(tx, where + "streaming width is 0");
    if (tx.get_byte_enable_ptr() != nullptr && tx.get_byte_enable_length() == 0)
      breach(tx, where + "byte-enable pointer with length 0");
    if (tx.get_response_status() != tlm::TLM_INCOMPLETE_RESPONSE)
      breach(tx, where + "response status not TLM_INCOMPLETE_RESPONSE on entry");
    if (in_flight_.count(&tx) != 0) breach(tx, where + "transaction already in flight");
  }

  void check_unchanged(const tlm::tlm_generic_payload& tx, const Snapshot& before,
                       const char* call) {
    const Snapshot now = snapshot_of(tx);
    if (now.command != before.command || now.address != before.address ||
        now.data != before.data || now.length != before.length ||
        now.enables != before.enables || now.enables_length != before.enables_length ||
        now.streaming_width != before.streaming_width)
      breach(tx, std::string(call) + ": the target changed an attribute it must leave alone");
  }

  void check_status_set(const tlm::tlm_generic_payload& tx, const char* when) {
    if (tx.get_response_status() == tlm::TLM_INCOMPLETE_RESPONSE)
      breach(tx, std::string(when) + " with response status still TLM_INCOMPLETE_RESPONSE");
  }

  void open_response(const tlm::tlm_generic_payload& tx, Flight& flight) {
    if (response_open_ != nullptr && response_open_ != &tx)
      breach(tx, "BEGIN_RESP while another response is open (response exclusion)");
    check_status_set(tx, "BEGIN_RESP");
    check_unchanged(tx, flight.snapshot, "BEGIN_RESP");
    close_request(&tx);
    flight.state = State::response;
    response_open_ = &tx;
  }

  void close_request(const tlm::tlm_generic_payload* tx) {
    if (request_open_ == tx) request_open_ = nullptr;
  }

  // Functional coverage (issue 37): every completed access, as the target answered it.
  void cover(const tlm::tlm_generic_payload& tx, testing_support::coverage::Transport transport,
             bool legal_override = false) const {
    if (!record_coverage || !testing_support::coverage::enabled() || tx.is_read() == tx.is_write())
      return;
    testing_support::coverage::record_access(
        tx.get_address(), tx.is_write(), tx.get_data_length(),
        legal_override || tx.get_response_status() == tlm::TLM_OK_RESPONSE, transport, tx.get_data_ptr());
  }

  void finish(tlm::tlm_generic_payload& tx) {
    cover(tx, testing_support::coverage::Transport::nb);
    close_request(&tx);
    if (response_open_ == &tx) response_open_ = nullptr;
    in_flight_.erase(&tx);
    ++nb_completed;
  }

  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
    ++b_calls;
    check_entry(tx, "b_transport");
    const Snapshot before = snapshot_of(tx);
    const sc_core::sc_time due = sc_core::sc_time_stamp() + delay;
    initiator_socket->b_transport(tx, delay);
    cover(tx, testing_support::coverage::Transport::b);
    check_unchanged(tx, before, "b_transport");
    check_status_set(tx, "b_transport returned");
    if (sc_core::sc_time_stamp() + delay < due)
      breach(tx, "b_transport moved the initiator's time backwards");
  }

  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& tx, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) {
    ++nb_calls;
    if (phase == tlm::BEGIN_REQ) {
      check_entry(tx, "BEGIN_REQ");
      if (request_open_ != nullptr)
        breach(tx, "BEGIN_REQ while another request is open (request exclusion)");
      in_flight_[&tx] = Flight{State::request, snapshot_of(tx)};
      request_open_ = &tx;
    } else if (phase == tlm::END_RESP) {
      auto it = in_flight_.find(&tx);
      if (it == in_flight_.end() || it->second.state != State::response)
        breach(tx, "END_RESP without an open response");
    } else {
      breach(tx, std::string("forward call with phase ") + phase.get_name());
    }
    const tlm::tlm_phase sent = phase;
    const tlm::tlm_sync_enum sync = initiator_socket->nb_transport_fw(tx, phase, delay);
    auto it = in_flight_.find(&tx);
    if (it == in_flight_.end()) return sync;
    Flight& flight = it->second;
    if (sent == tlm::END_RESP) {
      if (sync == tlm::TLM_UPDATED) breach(tx, "END_RESP answered TLM_UPDATED");
      finish(tx);
      return sync;
    }
    switch (sync) {
      case tlm::TLM_ACCEPTED:
        if (phase != sent) breach(tx, "TLM_ACCEPTED with a changed phase");
        break;
      case tlm::TLM_UPDATED:
        if (phase == tlm::END_REQ) {
          flight.state = State::end_request;
          close_request(&tx);
        } else if (phase == tlm::BEGIN_RESP) {
          open_response(tx, flight);
        } else {
          breach(tx, std::string("BEGIN_REQ answered TLM_UPDATED with phase ") + phase.get_name());
        }
        break;
      case tlm::TLM_COMPLETED:
        check_status_set(tx, "TLM_COMPLETED");
        check_unchanged(tx, flight.snapshot, "TLM_COMPLETED");
        finish(tx);
        break;
    }
    return sync;
  }

  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& tx, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) {
    ++nb_calls;
    auto it = in_flight_.find(&tx);
    if (it == in_flight_.end()) {
      breach(tx, std::string("backward call for a transaction not in flight, phase ") +
                     phase.get_name());
      return target_socket->nb_transport_bw(tx, phase, delay);
    }
    Flight& flight = it->second;
    if (phase == tlm::END_REQ) {
      if (flight.state != State::request) breach(tx, "END_REQ twice or after BEGIN_RESP");
      flight.state = State::end_request;
      close_request(&tx);
    } else if (phase == tlm::BEGIN_RESP) {
      if (flight.state == State::response) breach(tx, "BEGIN_RESP twice");
      open_response(tx, flight);
    } else {
      breach(tx, std::string("backward call with phase ") + phase.get_name());
    }
    const tlm::tlm_phase sent = phase;
    const tlm::tlm_sync_enum sync = target_socket->nb_transport_bw(tx, phase, delay);
    switch (sync) {
      case tlm::TLM_ACCEPTED:
        if (phase != sent) breach(tx, "TLM_ACCEPTED with a changed phase");
        break;
      case tlm::TLM_UPDATED:
        if (sent != tlm::BEGIN_RESP || phase != tlm::END_RESP)
          breach(tx, std::string("backward TLM_UPDATED with phase ") + phase.get_name());
        else
          finish(tx);
        break;
      case tlm::TLM_COMPLETED:
        finish(tx);
        break;
    }
    return sync;
  }

  unsigned int transport_dbg(tlm::tlm_generic_payload& tx) {
    ++dbg_calls;
    const unsigned length = tx.get_data_length();
    const unsigned done = initiator_socket->transport_dbg(tx);
    if (record_coverage && testing_support::coverage::enabled() && (tx.is_read() || tx.is_write()))
      testing_support::coverage::record_access(tx.get_address(), tx.is_write(), length, done == length && length > 0,
                                               testing_support::coverage::Transport::dbg, tx.get_data_ptr());
    if (done > length) breach(tx, "transport_dbg returned more bytes than asked for");
    return done;
  }

  std::map<const tlm::tlm_generic_payload*, Flight> in_flight_;
  const tlm::tlm_generic_payload* request_open_ = nullptr;
  const tlm::tlm_generic_payload* response_open_ = nullptr;
};

}  // namespace tlm_testing
}  // namespace specular
