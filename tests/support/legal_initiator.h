// An initiator that makes every choice the TLM-2.0 base protocol leaves to an
// initiator, for the tests and the fuzz target: b_transport, or nb_transport_fw with
// BEGIN_REQ (any annotated delay) answered at the end by TLM_COMPLETED, by TLM_UPDATED
// with END_RESP, or by TLM_ACCEPTED and a later END_RESP call — from any number of
// threads at once. It handles whatever the target answers (TLM_ACCEPTED then END_REQ
// and/or BEGIN_RESP backward, TLM_UPDATED with END_REQ or BEGIN_RESP, TLM_COMPLETED)
// and keeps request exclusion across its threads. No gtest here: the fuzz target uses it.
#pragma once

#include <cstdint>
#include <map>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "specular/systemc.h"

namespace specular {
namespace tlm_testing {

/// How one access travels; the nb paths name the initiator's answer to BEGIN_RESP.
enum class Path : std::uint8_t { b, nb_completed, nb_updated, nb_accepted, count };

inline const char* to_string(Path path) {
  switch (path) {
    case Path::b: return "b_transport";
    case Path::nb_completed: return "nb (BEGIN_RESP answered TLM_COMPLETED)";
    case Path::nb_updated: return "nb (BEGIN_RESP answered TLM_UPDATED/END_RESP)";
    case Path::nb_accepted: return "nb (BEGIN_RESP answered TLM_ACCEPTED, then END_RESP)";
    default: return "?";
  }
}

class LegalInitiator : public sc_core::sc_module {
 public:
  explicit LegalInitiator(sc_core::sc_module_name name) : sc_module(name) {
    socket.register_nb_transport_bw(this, &LegalInitiator::nb_transport_bw);
  }

  tlm_utils::simple_initiator_socket<LegalInitiator, 32> socket{"socket"};

  /// Streaming width argument of transport(): the data length (no streaming).
  static constexpr unsigned streaming_width_of_length = ~0u;

  /// One access from the calling thread; returns when it has completed (and the
  /// annotated time has passed) with the target's response status.
  tlm::tlm_response_status transport(Path path, tlm::tlm_command command, std::uint64_t address,
                                     void* data, unsigned length,
                                     const sc_core::sc_time& request_delay = sc_core::SC_ZERO_TIME,
                                     unsigned streaming_width = streaming_width_of_length,
                                     unsigned char* byte_enables = nullptr,
                                     unsigned byte_enable_length = 0) {
    tlm::tlm_generic_payload tx;
    tx.set_command(command);
    tx.set_address(address);
    tx.set_data_ptr(static_cast<unsigned char*>(data));
    tx.set_data_length(length);
    tx.set_streaming_width(streaming_width == streaming_width_of_length ? length : streaming_width);
    tx.set_byte_enable_ptr(byte_enables);
    tx.set_byte_enable_length(byte_enable_length);
    tx.set_dmi_allowed(false);
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    if (path == Path::b) {
      sc_core::sc_time delay = request_delay;
      socket->b_transport(tx, delay);
      wait(delay);
      return tx.get_response_status();
    }
    tx.set_mm(&no_free_);  // nb transactions carry a memory manager (IEEE 1666 §14.5)
    tx.acquire();
    run_nb(tx, path, request_delay);
    tx.release();
    return tx.get_response_status();
  }

  unsigned debug(tlm::tlm_command command, std::uint64_t address, void* data, unsigned length) {
    tlm::tlm_generic_payload tx;
    tx.set_command(command);
    tx.set_address(address);
    tx.set_data_ptr(static_cast<unsigned char*>(data));
    tx.set_data_length(length);
    return socket->transport_dbg(tx);
  }

  long nb_answers[3] = {0, 0, 0};  ///< BEGIN_REQ answered ACCEPTED, UPDATED, COMPLETED

 private:
  struct NoFree : tlm::tlm_mm_interface {
    void free(tlm::tlm_generic_payload*) override {}  // the payload lives on a caller's stack
  };
  struct Pending {
    Path path;
    bool responded = false;  ///< BEGIN_RESP arrived and was answered TLM_ACCEPTED
    bool finished = false;
    sc_core::sc_event wake;
  };

  void run_nb(tlm::tlm_generic_payload& tx, Path path, const sc_core::sc_time& request_delay) {
    while (request_open_) wait(request_free_);  // request exclusion, across all threads
    Pending pending;
    pending.path = path;
    pending_[&tx] = &pending;
    request_open_ = true;
    tlm::tlm_phase phase = tlm::BEGIN_REQ;
    sc_core::sc_time delay = request_delay;
    const tlm::tlm_sync_enum sync = socket->nb_transport_fw(tx, phase, delay);
    ++nb_answers[sync == tlm::TLM_ACCEPTED ? 0 : sync == tlm::TLM_UPDATED ? 1 : 2];
    if (sync == tlm::TLM_COMPLETED) {
      release_request();
      pending.finished = true;
    } else if (sync == tlm::TLM_UPDATED) {
      release_request();
      if (phase == tlm::BEGIN_RESP) pending.responded = true;  // answered below, END_RESP
    }
    wait(delay);
    while (!pending.finished && !pending.responded) wait(pending.wake);
    if (!pending.finished) {  // the response is ours to end with a forward call
      phase = tlm::END_RESP;
      delay = sc_core::SC_ZERO_TIME;
      socket->nb_transport_fw(tx, phase, delay);
      wait(delay);
    }
    pending_.erase(&tx);
  }

  tlm::tlm_sync_enum nb_transport_bw(tlm::tlm_generic_payload& tx, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) {
    Pending& pending = *pending_.at(&tx);
    release_request();  // END_REQ, or BEGIN_RESP (which implies it)
    if (phase == tlm::END_REQ) return tlm::TLM_ACCEPTED;
    switch (pending.path) {
      case Path::nb_completed:
        pending.finished = true;
        pending.wake.notify(delay);
        return tlm::TLM_COMPLETED;
      case Path::nb_updated:
        pending.finished = true;
        phase = tlm::END_RESP;
        pending.wake.notify(delay);
        return tlm::TLM_UPDATED;
      default:
        pending.responded = true;
        pending.wake.notify(delay);
        return tlm::TLM_ACCEPTED;
    }
  }

  void release_request() {
    if (!request_open_) return;
    request_open_ = false;
    request_free_.notify(sc_core::SC_ZERO_TIME);
  }

  NoFree no_free_;
  std::map<const tlm::tlm_generic_payload*, Pending*> pending_;
  bool request_open_ = false;
  sc_core::sc_event request_free_;
};

}  // namespace tlm_testing
}  // namespace specular
