#include "specular/twin/axi_target.h"

#include <stdexcept>
#include <string>

#include "axi_ip_model.h"
#include "same_formats.h"

namespace specular {

namespace {
constexpr std::uint32_t axi_okay = 0, axi_slverr = 2, axi_decerr = 3;
constexpr std::uint64_t status_offset = 0x00C;

// The TLM response `lt` gives for a refusal of `cause` (modules/src/tlm/target.cpp).
tlm::tlm_response_status response_for(ErrorCause cause) {
  switch (cause) {
    case ErrorCause::read_only:
    case ErrorCause::command: return tlm::TLM_COMMAND_ERROR_RESPONSE;
    case ErrorCause::address: return tlm::TLM_ADDRESS_ERROR_RESPONSE;
    case ErrorCause::burst: return tlm::TLM_BURST_ERROR_RESPONSE;
    case ErrorCause::byte_enable: return tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE;
    default: return tlm::TLM_GENERIC_ERROR_RESPONSE;
  }
}
}  // namespace

namespace {
const Config& checked(const Config& config) {
  if (!same_formats(config.widths, Widths{}))
    throw std::invalid_argument(
        "axi target: the IP is verilated at the default widths of docs/design.md only");
  const Config defaults{};
  if (config.normalisation != defaults.normalisation || config.saturation != defaults.saturation ||
      config.constants != defaults.constants)
    throw std::invalid_argument(std::string("axi target: the IP is verilated for constants ") +
                                to_string(defaults.constants) + ", normalisation " +
                                to_string(defaults.normalisation) + ", saturation " +
                                to_string(defaults.saturation) + " only; asked constants " +
                                to_string(config.constants) + ", normalisation " +
                                to_string(config.normalisation) + ", saturation " +
                                to_string(config.saturation));
  return config;
}
}  // namespace

SpecularAxiTarget::SpecularAxiTarget(sc_core::sc_module_name name, const Config& config,
                                     const sc_core::sc_time& clock_period)
    : SpecularTarget(name, checked(config), clock_period),
      ip_(std::make_unique<AxiIpModel>(config)) {}

SpecularAxiTarget::~SpecularAxiTarget() = default;

std::uint64_t SpecularAxiTarget::cycles() const { return ip_->cycles(); }

void SpecularAxiTarget::execute(const Operands&, const std::uint32_t*, std::size_t, std::uint32_t*,
                                Result&, sc_core::sc_time&) {
  // Never called: b_transport sends every access to the RTL.
}

tlm::tlm_response_status SpecularAxiTarget::access(tlm::tlm_generic_payload& tx,
                                                   std::uint64_t& cycles_taken) {
  const std::uint64_t before = ip_->cycles();
  const std::uint64_t address = tx.get_address();
  const unsigned length = tx.get_data_length();
  unsigned char* data = tx.get_data_ptr();
  const unsigned char* enables = tx.get_byte_enable_ptr();
  const unsigned enables_length = tx.get_byte_enable_length();
  const bool is_write = tx.get_command() == tlm::TLM_WRITE_COMMAND;
  auto finish = [&](tlm::tlm_response_status status) {
    cycles_taken = ip_->cycles() - before;
    return status;
  };
  if (tx.get_command() == tlm::TLM_IGNORE_COMMAND) return finish(tlm::TLM_OK_RESPONSE);
  // Bytes per transfer: 1 and 2 in one word, otherwise whole words.
  const bool sub_word = length == 1 || length == 2;
  if (!sub_word && (length == 0 || length % 4 != 0)) return finish(tlm::TLM_BURST_ERROR_RESPONSE);
  if (address > 0xFFFFFFFFull) return finish(tlm::TLM_ADDRESS_ERROR_RESPONSE);
  const unsigned transfers = sub_word ? 1 : length / 4;
  for (unsigned t = 0; t < transfers; ++t) {
    const std::uint64_t byte_address = address + 4ull * t;
    const unsigned lane0 = sub_word ? static_cast<unsigned>(address % 4) : 0;
    const unsigned bytes = sub_word ? length : 4;
    std::uint32_t word = 0, strobes = 0;
    for (unsigned b = 0; b < bytes; ++b) {
      const unsigned index = 4 * t + b;
      const bool enabled = enables == nullptr || enables[index % enables_length] != 0;
      if (enabled && lane0 + b < 4) strobes |= 1u << (lane0 + b);
      if (is_write && lane0 + b < 4) word |= static_cast<std::uint32_t>(data[index]) << (8 * (lane0 + b));
    }
    std::uint32_t resp;
    if (is_write) {
      resp = ip_->write(static_cast<std::uint32_t>(byte_address), word, strobes);
    } else {
      resp = ip_->read(static_cast<std::uint32_t>(byte_address), word);
      if (resp == axi_okay)
        for (unsigned b = 0; b < bytes && lane0 + b < 4; ++b)
          if (enables == nullptr || enables[(4 * t + b) % enables_length] != 0)
            data[4 * t + b] = static_cast<unsigned char>(word >> (8 * (lane0 + b)));
    }
    if (resp == axi_decerr) return finish(tlm::TLM_ADDRESS_ERROR_RESPONSE);
    if (resp == axi_slverr) {
      std::uint32_t status = 0;
      ip_->read(static_cast<std::uint32_t>(status_offset), status);
      return finish(response_for(static_cast<ErrorCause>((status >> 8) & 0xFFu)));
    }
  }
  return finish(tlm::TLM_OK_RESPONSE);
}

void SpecularAxiTarget::b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
  const bool level_before = ip_->done_irq();
  const std::uint64_t start = ip_->cycles();
  std::uint64_t cycles_taken = 0;
  tx.set_response_status(access(tx, cycles_taken));
  // done_irq: at the cycle the RTL's pin last changed inside this access (a fall at a
  // START and the rise at its end give the level after the access, as on lt).
  if (ip_->irq_changed_at() > start || ip_->done_irq() != level_before)
    rtl_done_irq(ip_->done_irq(), delay + clock_period() * static_cast<double>(ip_->irq_changed_at() - start));
  delay += clock_period() * static_cast<double>(cycles_taken);
  const std::string violation = ip_->take_violation();
  if (!violation.empty()) SC_REPORT_ERROR("specular/axi", violation.c_str());
}

unsigned int SpecularAxiTarget::transport_dbg(tlm::tlm_generic_payload& tx) {
  // Debug reads are AXI reads clocked in zero simulated time; debug writes are refused.
  if (tx.get_command() != tlm::TLM_READ_COMMAND) return 0;
  const unsigned length = tx.get_data_length();
  if (length == 0 || length % 4 != 0 || tx.get_address() % 4 != 0) return 0;
  unsigned char* data = tx.get_data_ptr();
  for (unsigned t = 0; t < length / 4; ++t) {
    std::uint32_t word = 0;
    if (ip_->read(static_cast<std::uint32_t>(tx.get_address() + 4ull * t), word) != axi_okay)
      return 4 * t;
    for (unsigned b = 0; b < 4; ++b) data[4 * t + b] = static_cast<unsigned char>(word >> (8 * b));
  }
  return length;
}

}  // namespace specular
