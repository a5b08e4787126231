// A generic bus: an address decoder with one target socket for the initiator and one
// initiator socket per window, as a third-party virtual platform's router is
// (riscv-vp's SimpleBus, Accellera's SimpleBusLT). It knows nothing of the IP.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

namespace soc {

class Bus : public sc_core::sc_module {
 public:
  using Output = tlm_utils::simple_initiator_socket<Bus, 32>;
  tlm_utils::simple_target_socket<Bus, 32> socket{"socket"};

  struct Window {
    std::uint64_t base, size;
    std::string name;
  };

  /// One output per window [base, base + size); `hop` is annotated on every access
  /// (the interconnect's own latency).
  Bus(sc_core::sc_module_name name, const std::vector<Window>& windows,
      const sc_core::sc_time& hop = sc_core::sc_time(5, sc_core::SC_NS))
      : sc_module(name), hop_(hop) {
    socket.register_b_transport(this, &Bus::b_transport);
    socket.register_transport_dbg(this, &Bus::transport_dbg);
    for (const Window& w : windows)
      outputs_.push_back({w, std::make_unique<Output>(w.name.c_str())});
  }

  Output& output(std::size_t i) { return *outputs_.at(i).socket; }

 private:
  struct Route {
    Window window;
    std::unique_ptr<Output> socket;
  };

  Route* decode(const tlm::tlm_generic_payload& tx) {
    for (Route& r : outputs_)
      if (tx.get_address() >= r.window.base && tx.get_address() - r.window.base < r.window.size)
        return &r;
    return nullptr;
  }

  // The target sees addresses relative to its window; the initiator gets its own
  // address back, as the base protocol wants of an interconnect.
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
    delay += hop_;
    Route* route = decode(tx);
    if (route == nullptr) return tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
    const std::uint64_t address = tx.get_address();
    tx.set_address(address - route->window.base);
    (*route->socket)->b_transport(tx, delay);
    tx.set_address(address);
  }

  unsigned int transport_dbg(tlm::tlm_generic_payload& tx) {
    Route* route = decode(tx);
    if (route == nullptr) return 0;
    const std::uint64_t address = tx.get_address();
    tx.set_address(address - route->window.base);
    const unsigned int bytes = (*route->socket)->transport_dbg(tx);
    tx.set_address(address);
    return bytes;
  }

  sc_core::sc_time hop_;
  std::vector<Route> outputs_;
};

/// Plain RAM behind the bus: any length, no byte enables, streaming width 0 or the
/// length; `latency` per access.
class Ram : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<Ram, 32> socket{"socket"};

  Ram(sc_core::sc_module_name name, std::size_t bytes,
      const sc_core::sc_time& latency = sc_core::sc_time(20, sc_core::SC_NS))
      : sc_module(name), bytes_(bytes, 0), latency_(latency) {
    socket.register_b_transport(this, &Ram::b_transport);
  }

 private:
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
    const std::uint64_t address = tx.get_address();
    const unsigned length = tx.get_data_length();
    if (address > bytes_.size() || length > bytes_.size() - address)
      return tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
    if (tx.get_byte_enable_ptr() != nullptr ||
        (tx.get_streaming_width() != 0 && tx.get_streaming_width() < length))
      return tx.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    if (tx.is_read())
      std::copy_n(&bytes_[address], length, tx.get_data_ptr());
    else if (tx.is_write())
      std::copy_n(tx.get_data_ptr(), length, &bytes_[address]);
    delay += latency_;
    tx.set_response_status(tlm::TLM_OK_RESPONSE);
  }

  std::vector<unsigned char> bytes_;
  sc_core::sc_time latency_;
};

}  // namespace soc
