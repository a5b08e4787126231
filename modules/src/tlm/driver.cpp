#include "specular/tlm/driver.h"

#include <algorithm>
#include <cstring>
#include <sstream>

#include "specular/tlm/response_name.h"

namespace specular {

using sc_core::sc_time;

SpecularDriver::SpecularDriver(port_type& port, std::uint64_t base,
                               tlm_utils::tlm_quantumkeeper& keeper)
    : port_(port), base_(base), keeper_(keeper) {}

void SpecularDriver::prepare(tlm::tlm_command command, std::uint32_t offset, unsigned char* data,
                             unsigned length) {
  tx_.set_command(command);
  tx_.set_address(base_ + offset);
  tx_.set_data_ptr(data);
  tx_.set_data_length(length);
  tx_.set_streaming_width(length);
  tx_.set_byte_enable_ptr(nullptr);
  tx_.set_byte_enable_length(0);
  tx_.set_dmi_allowed(false);
  tx_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
}

void SpecularDriver::transport(tlm::tlm_command command, std::uint32_t offset,
                               unsigned char* data, unsigned length, bool timed) {
  prepare(command, offset, data, length);

  sc_time local = keeper_.get_local_time();
  if (timed) {  // only operations are timed: sc_time_stamp() is a call into the kernel
    const sc_time before = sc_core::sc_time_stamp() + local;
    port_->b_transport(tx_, local);
    last_duration_ = sc_core::sc_time_stamp() + local - before;
  } else {
    port_->b_transport(tx_, local);
  }
  keeper_.set(local);
  if (keeper_.need_sync()) keeper_.sync();
  if (tx_.get_response_status() != tlm::TLM_OK_RESPONSE) fail(command, offset, length);
}

void SpecularDriver::fail(tlm::tlm_command command, std::uint32_t offset, unsigned length) {
  const tlm::tlm_response_status status = tx_.get_response_status();
  shared_loaded_ = false;  // the target may hold other values than we think
  // Ask the target why, as software would: read STATUS (through the same port).
  ErrorCause cause = ErrorCause::none;
  bool status_read = false;
  std::uint32_t status_word = 0;
  prepare(tlm::TLM_READ_COMMAND, offset_of(Reg::status),
          reinterpret_cast<unsigned char*>(&status_word), 4);
  sc_time local = keeper_.get_local_time();
  port_->b_transport(tx_, local);
  keeper_.set(local);
  if (tx_.get_response_status() == tlm::TLM_OK_RESPONSE) {
    status_read = true;
    cause = static_cast<ErrorCause>((status_word & status_bits::cause_mask) >> status_bits::cause_shift);
  }

  const RegisterInfo* row = decode(offset);
  std::ostringstream s;
  s << (command == tlm::TLM_READ_COMMAND ? "read of " : "write to ")
    << (row != nullptr ? row->name : "unmapped") << " (offset 0x" << std::hex << offset
    << std::dec << ", " << length << " bytes) refused: " << response_name(status);
  if (status_read)
    s << ", STATUS cause " << to_string(cause) << " (" << describe(cause) << ")";
  else
    s << ", and STATUS could not be read to tell why";
  throw TransportError(s.str(), status, cause);
}

std::uint32_t SpecularDriver::read(Reg reg) {
  std::uint32_t value = 0;
  transport(tlm::TLM_READ_COMMAND, offset_of(reg), reinterpret_cast<unsigned char*>(&value), 4);
  return value;
}

void SpecularDriver::write(Reg reg, std::uint32_t value) {
  transport(tlm::TLM_WRITE_COMMAND, offset_of(reg), reinterpret_cast<unsigned char*>(&value), 4);
}

void SpecularDriver::read_words(std::uint32_t offset, std::uint32_t* words, std::size_t count) {
  transport(tlm::TLM_READ_COMMAND, offset, reinterpret_cast<unsigned char*>(words),
            static_cast<unsigned>(4 * count));
}

void SpecularDriver::write_words(std::uint32_t offset, const std::uint32_t* words,
                                 std::size_t count) {
  // The target only reads a write's data; the generic payload's pointer is not const.
  transport(tlm::TLM_WRITE_COMMAND, offset,
            reinterpret_cast<unsigned char*>(const_cast<std::uint32_t*>(words)),
            static_cast<unsigned>(4 * count), true);
}

void SpecularDriver::load_shared(code_t n, const std::array<code_t, 3>& rgb) {
  if (!shared_loaded_ || n != loaded_n_) write(Reg::n, static_cast<std::uint32_t>(n));
  loaded_n_ = n;
  const Reg channel[3] = {Reg::r, Reg::g, Reg::b};
  for (int ch = 0; ch < 3; ++ch) {
    if (!shared_loaded_ || rgb[ch] != loaded_rgb_[ch])
      write(channel[ch], static_cast<std::uint32_t>(rgb[ch]));
    loaded_rgb_[ch] = rgb[ch];
  }
  shared_loaded_ = true;
}

std::array<std::int32_t, 3> SpecularDriver::compute(const Operands& in) {
  load_shared(in.n, in.rgb);
  write(Reg::cos, static_cast<std::uint32_t>(in.cos));
  std::uint32_t start = control_bits::start;
  transport(tlm::TLM_WRITE_COMMAND, offset_of(Reg::control),
            reinterpret_cast<unsigned char*>(&start), 4, true);
  operation_duration_ = last_duration_;
  return {static_cast<std::int32_t>(read(Reg::out_r)), static_cast<std::int32_t>(read(Reg::out_g)),
          static_cast<std::int32_t>(read(Reg::out_b))};
}

std::array<std::int32_t, 3> SpecularDriver::compute_burst(const Operands& in) {
  // OPERANDS words 0–5: COS, N, R, G, B, CONTROL; RESULTS: OUT_R, OUT_G, OUT_B.
  std::uint32_t operands[operand_words] = {
      static_cast<std::uint32_t>(in.cos),    static_cast<std::uint32_t>(in.n),
      static_cast<std::uint32_t>(in.rgb[0]), static_cast<std::uint32_t>(in.rgb[1]),
      static_cast<std::uint32_t>(in.rgb[2]), control_bits::start};
  write_words(offset_of(Reg::operands), operands, operand_words);
  loaded_n_ = in.n;  // what the target now holds (a refusal throws before this)
  loaded_rgb_ = in.rgb;
  shared_loaded_ = true;
  operation_duration_ = last_duration_;
  std::array<std::int32_t, 3> out;
  read_words(offset_of(Reg::results), reinterpret_cast<std::uint32_t*>(out.data()), 3);
  return out;
}

namespace {
code_t join(std::uint32_t low, std::uint32_t high) {
  return static_cast<code_t>((static_cast<std::uint64_t>(high) << 32) | low);
}
}  // namespace

Result SpecularDriver::compute_inspected(const Operands& in) {
  Result r;
  const auto out = compute(in);
  for (int ch = 0; ch < 3; ++ch) r.out[ch] = out[ch];
  r.reg1 = read(Reg::reg1);
  r.reg9_pass1 = join(read(Reg::reg9_pass1_lo), read(Reg::reg9_pass1_hi));
  r.reg9_pass2 = join(read(Reg::reg9_pass2_lo), read(Reg::reg9_pass2_hi));
  r.rom38_k = read(Reg::rom38_k);
  r.norm39 = static_cast<std::int32_t>(read(Reg::norm39));
  return r;
}

void SpecularDriver::compute_batch(code_t n, const std::array<code_t, 3>& rgb,
                                   const std::uint32_t* cos, std::size_t count, std::int32_t* out) {
  load_shared(n, rgb);
  operation_duration_ = sc_time();
  for (std::size_t done = 0; done < count;) {
    const std::size_t chunk = std::min<std::size_t>(count - done, batch_capacity);
    write_words(offset_of(Reg::batch_cos), cos + done, chunk);
    operation_duration_ += last_duration_;
    read_words(offset_of(Reg::batch_out), reinterpret_cast<std::uint32_t*>(out + 3 * done),
               3 * chunk);
    done += chunk;
  }
}

}  // namespace specular
