#include "platform.h"

#include <algorithm>
#include <cstring>
#include <sstream>

namespace specular {
namespace vp {

using sc_core::sc_time;

// ---- memory ------------------------------------------------------------------------

Memory::Memory(sc_core::sc_module_name name, std::size_t bytes, const sc_time& latency,
               const sc_time& word_latency)
    : sc_module(name), socket("socket"), bytes_(bytes, 0), latency_(latency),
      word_latency_(word_latency) {
  socket.register_b_transport(this, &Memory::b_transport);
  socket.register_transport_dbg(this, &Memory::transport_dbg);
}

bool Memory::access(tlm::tlm_generic_payload& tx) {
  const std::uint64_t address = tx.get_address();
  const unsigned length = tx.get_data_length();
  if (address > bytes_.size() || length > bytes_.size() - address) {
    tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
    return false;
  }
  if (tx.get_byte_enable_ptr() != nullptr) {
    tx.set_response_status(tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE);
    return false;
  }
  if (tx.get_streaming_width() < length) {
    tx.set_response_status(tlm::TLM_BURST_ERROR_RESPONSE);
    return false;
  }
  if (tx.is_read())
    std::memcpy(tx.get_data_ptr(), &bytes_[address], length);
  else if (tx.is_write())
    std::memcpy(&bytes_[address], tx.get_data_ptr(), length);
  tx.set_response_status(tlm::TLM_OK_RESPONSE);
  return true;
}

void Memory::b_transport(tlm::tlm_generic_payload& tx, sc_time& delay) {
  if (access(tx)) delay += latency_ + word_latency_ * ((tx.get_data_length() + 3) / 4);
}

unsigned int Memory::transport_dbg(tlm::tlm_generic_payload& tx) {
  return access(tx) ? tx.get_data_length() : 0;
}

// ---- router ------------------------------------------------------------------------

Router::Router(sc_core::sc_module_name name, const std::vector<Range>& ranges)
    : sc_module(name), socket("socket") {
  socket.register_b_transport(this, &Router::b_transport);
  socket.register_transport_dbg(this, &Router::transport_dbg);
  for (const Range& r : ranges)
    windows_.push_back({r.base, r.size, std::make_unique<Output>(r.name.c_str())});
}

Router::Window* Router::decode(tlm::tlm_generic_payload& tx) {
  const std::uint64_t address = tx.get_address();
  for (Window& w : windows_)
    if (address >= w.base && address - w.base < w.size) return &w;
  return nullptr;
}

void Router::b_transport(tlm::tlm_generic_payload& tx, sc_time& delay) {
  Window* w = decode(tx);
  if (w == nullptr) return tx.set_response_status(tlm::TLM_ADDRESS_ERROR_RESPONSE);
  const std::uint64_t address = tx.get_address();
  tx.set_address(address - w->base);
  (*w->socket)->b_transport(tx, delay);
  tx.set_address(address);
}

unsigned int Router::transport_dbg(tlm::tlm_generic_payload& tx) {
  Window* w = decode(tx);
  if (w == nullptr) return 0;
  const std::uint64_t address = tx.get_address();
  tx.set_address(address - w->base);
  const unsigned int bytes = (*w->socket)->transport_dbg(tx);
  tx.set_address(address);
  return bytes;
}

// ---- CPU ---------------------------------------------------------------------------

Cpu::Cpu(sc_core::sc_module_name name, const Frame& frame)
    : sc_module(name), socket("socket"), frame_(frame), ip_(socket, ip_base, keeper_) {
  SPECULAR_HAS_PROCESS(Cpu);
  SC_THREAD(program);
}

void Cpu::memory_transport(tlm::tlm_command command, std::uint64_t address, void* data,
                           unsigned length) {
  tx_.set_command(command);
  tx_.set_address(address);
  tx_.set_data_ptr(static_cast<unsigned char*>(data));
  tx_.set_data_length(length);
  tx_.set_streaming_width(length);
  tx_.set_byte_enable_ptr(nullptr);
  tx_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  sc_time local = keeper_.get_local_time();
  socket->b_transport(tx_, local);
  keeper_.set(local);
  if (keeper_.need_sync()) keeper_.sync();
  if (tx_.get_response_status() != tlm::TLM_OK_RESPONSE) {
    std::ostringstream s;
    s << "memory access at 0x" << std::hex << address << std::dec << " (" << length
      << " bytes) refused: " << tx_.get_response_string();
    throw std::runtime_error(s.str());
  }
}

void Cpu::memory_write(std::uint64_t address, const void* data, unsigned length) {
  memory_transport(tlm::TLM_WRITE_COMMAND, address, const_cast<void*>(data), length);
}

void Cpu::memory_read(std::uint64_t address, void* data, unsigned length) {
  memory_transport(tlm::TLM_READ_COMMAND, address, data, length);
}

void Cpu::program() {
  try {
    tlm::tlm_global_quantum::instance().set(sc_time(1, sc_core::SC_US));
    keeper_.reset();
    if (ip_.read(Reg::id) != device_id) throw std::runtime_error("no specular IP at its address");

    const int size = frame_.size, width = frame_.width();
    const unsigned panel_bytes = 3u * static_cast<unsigned>(size);
    std::vector<std::uint32_t> cos(static_cast<std::size_t>(size));
    std::vector<std::uint8_t> row(3u * static_cast<std::size_t>(width));

    // Geometry: normals → cos λ = N·H per pixel (outside the sphere: a marker), and
    // the diffuse base colour, the same in every panel.
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        Vec normal{};
        const bool inside = normal_at(x, y, size, normal);
        cos[x] = inside ? cos_code(normal) : outside;
        const std::array<std::uint8_t, 3> base = inside ? base_colour(normal) : background;
        for (std::size_t p = 0; p < Frame::panel_count; ++p)
          std::copy(base.begin(), base.end(), &row[3 * (p * size + x)]);
      }
      memory_write(frame_.cos_buffer() + 4ull * size * y, cos.data(), 4u * size);
      memory_write(frame_.frame_buffer() + 3ull * width * y, row.data(), 3u * width);
    }

    // Specular: per panel and row, the sphere's span goes through BATCH_COS in one
    // burst; the CPU adds the IP's R, G, B to the row's pixels.
    std::vector<std::int32_t> out(3u * static_cast<std::size_t>(size));
    std::vector<std::uint8_t> pixels(panel_bytes);
    const std::array<code_t, 3> light{light_rgb[0], light_rgb[1], light_rgb[2]};
    for (std::size_t p = 0; p < Frame::panel_count; ++p) {
      for (int y = 0; y < size; ++y) {
        memory_read(frame_.cos_buffer() + 4ull * size * y, cos.data(), 4u * size);
        const auto first = std::find_if(cos.begin(), cos.end(), [](std::uint32_t c) { return c != outside; });
        if (first == cos.end()) continue;
        const auto last = std::find(first, cos.end(), outside);
        const std::size_t x0 = static_cast<std::size_t>(first - cos.begin());
        const std::size_t count = static_cast<std::size_t>(last - first);
        ip_.compute_batch(panel_n[p], light, &*first, count, out.data());
        ip_busy += ip_.operation_duration();
        operations += count;
        ip_bursts += (count + batch_capacity - 1) / batch_capacity;

        const std::uint64_t line = frame_.frame_buffer() + 3ull * (width * y + p * size);
        memory_read(line, pixels.data(), panel_bytes);
        for (std::size_t i = 0; i < count; ++i)
          for (int ch = 0; ch < 3; ++ch) {
            std::uint8_t& pixel = pixels[3 * (x0 + i) + ch];
            pixel = add_specular(pixel, out[3 * i + ch]);
          }
        memory_write(line, pixels.data(), panel_bytes);
      }
    }
    keeper_.sync();
    finished_at = sc_core::sc_time_stamp();
  } catch (const std::exception& e) {
    failure = e.what();
  }
  sc_core::sc_stop();
}

}  // namespace vp
}  // namespace specular
