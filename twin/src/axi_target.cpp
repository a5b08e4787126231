#include "specular/twin/axi_target.h"

#include <stdexcept>
#include <string>

#include "axi_ip_model.h"
#include "same_formats.h"

namespace specular {

namespace {
constexpr std::uint32_t axi_okay = 0, axi_slverr = 2, axi_decerr = 3;

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

void SpecularAxiTarget::stall_at_random(std::uint32_t seed, unsigned percent) {
  if (percent > 50)
    throw std::invalid_argument("axi target: stall percent " + std::to_string(percent) +
                                " outside 0..50 (READY must come within the 64-cycle limit of a transfer)");
  ip_->stall_at_random(seed, percent);
}

void SpecularAxiTarget::execute(const Operands&, const std::uint32_t*, std::size_t, std::uint32_t*,
                                Result&, sc_core::sc_time&) {
  // Never called: b_transport sends every access to the RTL.
}

tlm::tlm_response_status SpecularAxiTarget::access(tlm::tlm_generic_payload& tx,
                                                   std::uint64_t& cycles_taken) {
  const std::uint64_t before = ip_->cycles();
  auto finish = [&](tlm::tlm_response_status status) {
    cycles_taken = ip_->cycles() - before;
    return status;
  };
  const Attempt attempt{tx.get_command(), tx.get_address(), tx.get_data_length()};
  const bool is_write = attempt.command == tlm::TLM_WRITE_COMMAND;
  unsigned char* data = tx.get_data_ptr();
  // A hole (or beyond the map) is the RTL's to refuse: one transfer there, DECERR. The
  // IP has no batch windows (BATCH_CAPACITY 0, docs/decisions.md): holes too.
  const RegisterInfo* decoded = decode(attempt.address & ~std::uint64_t{3});
  const bool hole = decoded == nullptr || decoded->reg == Reg::batch_cos || decoded->reg == Reg::batch_out;
  if (attempt.address <= 0xFFFFFFFFull && hole && (is_write || attempt.command == tlm::TLM_READ_COMMAND)) {
    std::uint32_t word = 0;
    return finish(transfer(attempt, attempt.address, is_write, word, 0xF));
  }
  // Then the payload's shape, by lt's own checks: AXI4-Lite cannot carry what they
  // refuse (a misaligned half word, 8 bytes off a doubleword, a streaming width, byte
  // enables that leave a byte out, an address above 32 bits), so such an access never
  // reaches the RTL and its STATUS stays as it was.
  const RegisterInfo* row = nullptr;
  if (const tlm::tlm_response_status shape = check_access(tx, attempt, row); shape != tlm::TLM_OK_RESPONSE) {
    // A burst running past its window is refused at the window's end, as lt names it;
    // where that is a hole, one transfer there lets the RTL refuse it and set STATUS.
    const bool runaway = row != nullptr && row->words > 1 && attempt.address % 4 == 0 &&
                         attempt.length > 0 && attempt.length % 4 == 0 &&
                         (attempt.address - row->offset) / 4 + attempt.length / 4 > row->words;
    if (shape == tlm::TLM_ADDRESS_ERROR_RESPONSE && runaway && decode(row->end()) == nullptr &&
        (is_write || attempt.command == tlm::TLM_READ_COMMAND)) {
      std::uint32_t word = 0;
      return finish(transfer(attempt, row->end(), is_write, word, 0xF));
    }
    return finish(shape);
  }
  if (attempt.command == tlm::TLM_IGNORE_COMMAND) return finish(tlm::TLM_OK_RESPONSE);
  if (attempt.length < 4) {  // one transfer: those lanes, their strobes
    const unsigned lane = static_cast<unsigned>(attempt.address % 4);
    std::uint32_t word = 0, strobes = 0;
    for (unsigned b = 0; b < attempt.length; ++b) {
      strobes |= 1u << (lane + b);
      if (is_write) word |= static_cast<std::uint32_t>(data[b]) << (8 * (lane + b));
    }
    const tlm::tlm_response_status status = transfer(attempt, attempt.address, is_write, word, strobes);
    if (status == tlm::TLM_OK_RESPONSE && !is_write)
      for (unsigned b = 0; b < attempt.length; ++b) data[b] = static_cast<unsigned char>(word >> (8 * (lane + b)));
    return finish(status);
  }
  const unsigned words = attempt.length / 4;
  const auto word_at = [&](unsigned i) {
    std::uint32_t word = 0;
    for (unsigned b = 0; b < 4; ++b) word |= static_cast<std::uint32_t>(data[4 * i + b]) << (8 * b);
    return word;
  };
  // All or nothing, as on lt: a word the map refuses is sent alone, so that the RTL
  // refuses it and sets STATUS, and no other word of the access is written.
  if (is_write)
    for (unsigned i = 0; i < words; ++i)
      if (map_refuses(*row, attempt.address, i, word_at(i))) {
        std::uint32_t word = word_at(i);
        const tlm::tlm_response_status status = transfer(attempt, attempt.address + 4ull * i, true, word, 0xF);
        if (status == tlm::TLM_OK_RESPONSE)
          SC_REPORT_ERROR("specular/axi", "the RTL took a word the register map refuses");
        return finish(status);
      }
  for (unsigned i = 0; i < words; ++i) {
    std::uint32_t word = is_write ? word_at(i) : 0;
    const tlm::tlm_response_status status = transfer(attempt, attempt.address + 4ull * i, is_write, word, 0xF);
    if (status != tlm::TLM_OK_RESPONSE) return finish(status);
    if (!is_write)
      for (unsigned b = 0; b < 4; ++b) data[4 * i + b] = static_cast<unsigned char>(word >> (8 * b));
  }
  return finish(tlm::TLM_OK_RESPONSE);
}

bool SpecularAxiTarget::map_refuses(const RegisterInfo& row, std::uint64_t address, unsigned index,
                                    std::uint32_t value) const {
  // 8 bytes on single registers cover two rows; a window's words are its rows' words.
  const RegisterInfo* word_row = row.words == 1 ? decode(address + 4ull * index) : &row;
  if (word_row == nullptr || word_row->access == Access::read_only) return true;
  if (word_row->reg == Reg::status) return false;  // W1C: any value
  const std::uint32_t first = static_cast<std::uint32_t>(address - row.offset) / 4;
  const Reg reg = word_row->reg == Reg::operands ? operand_register(first + index) : word_row->reg;
  return check_value(reg, value) != ErrorCause::none;
}

tlm::tlm_response_status SpecularAxiTarget::transfer(const Attempt& attempt, std::uint64_t address,
                                                     bool is_write, std::uint32_t& word,
                                                     std::uint32_t strobes) {
  const auto axi_address = static_cast<std::uint32_t>(address);
  const std::uint32_t resp = is_write ? ip_->write(axi_address, word, strobes) : ip_->read(axi_address, word);
  if (resp == axi_okay) {
    if (is_write) charge_write(address, word, strobes);
    return tlm::TLM_OK_RESPONSE;
  }
  ErrorCause cause = ErrorCause::address;
  if (resp == axi_slverr) {
    std::uint32_t status = 0;
    ip_->read(offset_of(Reg::status), status);
    cause = static_cast<ErrorCause>((status & status_bits::cause_mask) >> status_bits::cause_shift);
  }
  // The first refusal of each cause is logged as lt logs it (the RTL set STATUS and
  // ERROR_ADDRESS = this transfer's address).
  const RegisterInfo* row = decode(address & ~std::uint64_t{3});
  const char* field = row != nullptr ? row->name : "address";
  const Why why = cause == ErrorCause::address ? Why{"address", address, address_rule(address)}
                  : cause == ErrorCause::read_only ? Why{field, address, read_only_rule}
                                                   : Why{field, word, describe(cause)};
  const tlm::tlm_response_status status = resp == axi_decerr ? tlm::TLM_ADDRESS_ERROR_RESPONSE : response_for(cause);
  report_refusal(status, cause, axi_address, attempt, why);
  return status;
}

void SpecularAxiTarget::charge_write(std::uint64_t address, std::uint32_t word, std::uint32_t strobes) {
  energy::EnergyMeter* const meter = energy_meter();
  if (meter == nullptr) return;
  const RegisterInfo* row = decode(address & ~std::uint64_t{3});
  if (row == nullptr) return;
  const Reg reg = row->reg == Reg::operands ? operand_register(static_cast<std::uint32_t>(address - row->offset) / 4)
                                            : row->reg;
  std::uint32_t mask = 0;
  for (unsigned lane = 0; lane < 4; ++lane)
    if (strobes & (1u << lane)) mask |= 0xFFu << (8 * lane);
  const auto merge = [&](std::uint32_t& held) { held = (held & ~mask) | (word & mask); };
  switch (reg) {
    case Reg::cos: return merge(operands_.cos_word);
    case Reg::n: return merge(operands_.n_word);
    case Reg::r: return merge(operands_.rgb_words[0]);
    case Reg::g: return merge(operands_.rgb_words[1]);
    case Reg::b: return merge(operands_.rgb_words[2]);
    case Reg::control:
      if ((word & mask & control_bits::start) != 0) {
        Operands op;
        op.cos = operands_.cos_word;
        op.n = operands_.n_word;
        for (int ch = 0; ch < 3; ++ch) op.rgb[ch] = operands_.rgb_words[ch];
        meter->operation(config(), op);
      }
      return;
    default: return;
  }
}

void SpecularAxiTarget::b_transport(tlm::tlm_generic_payload& tx, sc_core::sc_time& delay) {
  const std::uint64_t start = ip_->cycles();
  std::uint64_t cycles_taken = 0;
  tx.set_response_status(access(tx, cycles_taken));
  // done_irq: each edge of the RTL's pin at its cycle inside this access (a START that
  // meets done raised: the fall, then the rise at the operation's end, as on lt).
  for (const auto& [cycle, level] : ip_->take_irq_edges())
    rtl_done_irq(level, delay + clock_period() * static_cast<double>(cycle - start));
  delay += clock_period() * static_cast<double>(cycles_taken);
  const std::string violation = ip_->take_violation();
  if (!violation.empty()) SC_REPORT_ERROR("specular/axi", violation.c_str());
}

unsigned int SpecularAxiTarget::transport_dbg(tlm::tlm_generic_payload& tx) {
  // Debug reads are AXI reads of mapped words clocked in zero simulated time; debug
  // writes are refused.
  if (tx.get_command() != tlm::TLM_READ_COMMAND) return 0;
  const unsigned length = tx.get_data_length();
  if (length == 0 || length % 4 != 0 || tx.get_address() % 4 != 0) return 0;
  unsigned char* data = tx.get_data_ptr();
  for (unsigned t = 0; t < length / 4; ++t) {
    // A hole stops the read before the bus: an AXI read of it would set STATUS.error,
    // and a debug access has no side effects.
    const RegisterInfo* row = decode(tx.get_address() + 4ull * t);
    if (row == nullptr || row->reg == Reg::batch_cos || row->reg == Reg::batch_out) return 4 * t;
    std::uint32_t word = 0;
    if (ip_->read(static_cast<std::uint32_t>(tx.get_address() + 4ull * t), word) != axi_okay)
      return 4 * t;
    for (unsigned b = 0; b < 4; ++b) data[4 * t + b] = static_cast<unsigned char>(word >> (8 * b));
  }
  return length;
}

}  // namespace specular
