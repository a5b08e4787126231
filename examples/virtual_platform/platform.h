// The example virtual platform: a CPU (initiator thread), a router, a memory and the
// specular IP (the TLM `lt` target), as in Accellera's LT examples.
//
//   cpu.socket → router ─┬─ 0x0000_0000 memory (cos buffer, frame buffer)
//                        └─ 0x4000_0000 specular IP (docs/tlm.md register map)
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "scene.h"
#include "specular/specular.h"

namespace specular {
namespace vp {

/// RAM: bursts of any length, no byte enables; `latency` per access plus
/// `word_latency` per 32-bit word.
class Memory : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<Memory, 32> socket;

  Memory(sc_core::sc_module_name name, std::size_t bytes,
         const sc_core::sc_time& latency = sc_core::sc_time(20, sc_core::SC_NS),
         const sc_core::sc_time& word_latency = sc_core::sc_time(1, sc_core::SC_NS));

  const std::vector<unsigned char>& contents() const { return bytes_; }

 private:
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);
  unsigned int transport_dbg(tlm::tlm_generic_payload& tx);
  bool access(tlm::tlm_generic_payload& tx);

  std::vector<unsigned char> bytes_;
  sc_core::sc_time latency_, word_latency_;
};

/// Address decoder: forwards each transaction to the output whose window holds its
/// address, with the address made relative to the window; TLM_ADDRESS_ERROR_RESPONSE
/// elsewhere.
class Router : public sc_core::sc_module {
 public:
  using Output = tlm_utils::simple_initiator_socket<Router, 32>;
  tlm_utils::simple_target_socket<Router, 32> socket;

  /// One output per window [base, base + size); sockets are made here, at
  /// construction, as SystemC requires.
  struct Range {
    std::uint64_t base, size;
    std::string name;
  };
  Router(sc_core::sc_module_name name, const std::vector<Range>& ranges);
  /// The output socket of ranges[i]; bind it to a target.
  Output& output(std::size_t i) { return *windows_.at(i).socket; }

 private:
  struct Window {
    std::uint64_t base, size;
    std::unique_ptr<Output> socket;
  };
  Window* decode(tlm::tlm_generic_payload& tx);
  void b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);
  unsigned int transport_dbg(tlm::tlm_generic_payload& tx);

  std::vector<Window> windows_;
};

/// The platform's address map.
constexpr std::uint64_t memory_base = 0x00000000;
constexpr std::uint64_t ip_base = 0x40000000;

/// What the CPU renders and where it keeps it in memory.
struct Frame {
  int size = 256;  ///< panel width and height
  int width() const { return size * static_cast<int>(panel_count); }
  static constexpr std::size_t panel_count = panel_n.size();
  std::uint64_t cos_buffer() const { return memory_base; }  ///< size² COS words
  std::uint64_t frame_buffer() const {                      ///< width × size RGB bytes
    return memory_base + ((4ull * size * size + 0xFFF) & ~0xFFFull);
  }
  std::size_t memory_bytes() const {
    return static_cast<std::size_t>(frame_buffer() - memory_base) + 3ull * width() * size;
  }
};

/// The CPU: a program in an SC_THREAD, under a 1 µs quantum keeper. It checks the
/// IP's ID, computes the sphere's normals and writes cos λ to memory, paints the
/// diffuse base into the frame buffer, then for each panel and row reads the cos
/// codes from memory, runs them through the IP's batch window (one burst per row),
/// adds the specular result to the row's pixels and writes them back.
class Cpu : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<Cpu, 32> socket;

  Cpu(sc_core::sc_module_name name, const Frame& frame);

  /// Figures of the run, for the summary line.
  std::uint64_t operations = 0;
  std::uint64_t ip_bursts = 0;
  sc_core::sc_time ip_busy;     ///< annotated start → results, summed
  sc_core::sc_time finished_at;
  std::string failure;          ///< non-empty if the program stopped on an error

 private:
  void program();
  void memory_write(std::uint64_t address, const void* data, unsigned length);
  void memory_read(std::uint64_t address, void* data, unsigned length);
  void memory_transport(tlm::tlm_command command, std::uint64_t address, void* data,
                        unsigned length);

  Frame frame_;
  tlm_utils::tlm_quantumkeeper keeper_;
  SpecularDriver ip_;
  tlm::tlm_generic_payload tx_;
};

}  // namespace vp
}  // namespace specular
