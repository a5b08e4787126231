#include "specular/tlm/target.h"

#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

#include "specular/report_ids.h"
#include "specular/tlm/response_name.h"

namespace specular {

using sc_core::sc_time;

namespace {

// The single-START path writes pins 24–26 straight into OUT_R, OUT_G, OUT_B.
static_assert(index_of(Reg::out_g) == index_of(Reg::out_r) + 1 &&
                  index_of(Reg::out_b) == index_of(Reg::out_r) + 2,
              "OUT_R, OUT_G, OUT_B must be consecutive rows");

void require_32_bits(const char* what, const FixedFormat& format) {
  if (format.width() > 32)
    throw std::invalid_argument(std::string("TLM target: ") + what + " format " + format.name() +
                                " is " + std::to_string(format.width()) +
                                " bits wide; its 32-bit register holds at most 32");
}

std::uint32_t load(const unsigned char* data) {
  std::uint32_t value;
  std::memcpy(&value, data, 4);
  return value;
}

void store(unsigned char* data, std::uint32_t value) { std::memcpy(data, &value, 4); }

bool all_bytes_enabled(const unsigned char* enables, unsigned enables_length, unsigned length) {
  if (enables_length == 0) return false;
  for (unsigned i = 0; i < length; ++i)
    if (enables[i % enables_length] != TLM_BYTE_ENABLED) return false;
  return true;
}

const char* command_name(tlm::tlm_command command) {
  switch (command) {
    case tlm::TLM_READ_COMMAND: return "read";
    case tlm::TLM_WRITE_COMMAND: return "write";
    case tlm::TLM_IGNORE_COMMAND: return "ignore";
  }
  return "unknown command";
}

/// Registers whose sub-word writes merge into the stored word (docs/integration.md).
bool takes_sub_word_writes(Reg reg) {
  switch (reg) {
    case Reg::status:
    case Reg::control:
    case Reg::cos:
    case Reg::n:
    case Reg::r:
    case Reg::g:
    case Reg::b: return true;
    default: return false;
  }
}

// ERROR_ADDRESS is 32 bits: an address beyond them shows as this value, which no
// register has (the map ends at map_size), rather than as its low bits.
constexpr std::uint32_t error_address_beyond_32_bits = 0xFFFFFFFFu;

std::uint32_t low_word(code_t code) { return static_cast<std::uint32_t>(code); }
std::uint32_t high_word(code_t code) {
  return static_cast<std::uint32_t>(static_cast<std::uint64_t>(code) >> 32);
}

}  // namespace

SpecularTarget::SpecularTarget(sc_core::sc_module_name name, const Config& config,
                               const sc_time& clock_period)
    : sc_module(name),
      socket("socket"),
      done_irq("done_irq"),
      config_(config),
      formats_(config.widths),
      period_(clock_period),
      batch_cos_(batch_capacity, 0),
      batch_out_(3 * batch_capacity, 0),
      irq_default_("done_irq_default", done_irq) {
  SPECULAR_HAS_PROCESS(SpecularTarget);
  require_32_bits("COS", formats_.cos);
  require_32_bits("N", formats_.n);
  require_32_bits("RGB", formats_.rgb);
  require_32_bits("OUT", formats_.out);
  require_32_bits("ROM38_K", formats_.rom38);
  require_32_bits("NORM39", formats_.norm);
  if (clock_period <= sc_core::SC_ZERO_TIME)
    throw std::invalid_argument("TLM target: clock period " + clock_period.to_string() +
                                " must be positive");

  for (const RegisterInfo& row : register_map)
    if (row.words == 1) words_[index_of(row.reg)] = row.reset;
  word(Reg::config) = config_word(config_);
  word(Reg::pin19_h) = static_cast<std::uint32_t>(pin19_code(config_));
  word(Reg::pin20_a) = static_cast<std::uint32_t>(pin20_code(config_));

  socket.register_b_transport(this, &SpecularTarget::transport);
  socket.register_transport_dbg(this, &SpecularTarget::transport_dbg);

  SC_THREAD(sample_power);

  done_irq.initialize(false);
  SC_METHOD(drive_irq);
  sensitive << irq_event_;
  dont_initialize();
}

// ---- bus checks --------------------------------------------------------------------

tlm::tlm_response_status SpecularTarget::check_access(const tlm::tlm_generic_payload& tx,
                                                      const Attempt& attempt,
                                                      const RegisterInfo*& row) {
  const std::uint64_t address = attempt.address;
  const unsigned length = attempt.length;
  row = decode(address & ~std::uint64_t{3});
  if (row == nullptr)
    return refuse(tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, address, attempt,
                  {"address", address, address_rule(address)});
  const bool sub_word = length == 1 || length == 2;
  // Natural alignment: a sub-word inside its word, words and bursts on a word, a
  // doubleword on two registers at a doubleword offset (a 64-bit core's access).
  if (address % (sub_word ? length : 4) != 0)
    return refuse(tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, address, attempt,
                  {"address", address,
                   "an access of 1, 2 or 4 bytes must be aligned to its length, bursts to a word"});
  if (length == 0 || !(sub_word || length % 4 == 0))
    return refuse(tlm::TLM_BURST_ERROR_RESPONSE, ErrorCause::burst, address, attempt,
                  {"data_length", length,
                   "registers take 1, 2, 4 or 8 bytes, windows a multiple of 4"});
  if (row->words == 1 && length > 4 && (length != 8 || address % 8 != 0))
    return refuse(tlm::TLM_BURST_ERROR_RESPONSE, ErrorCause::burst, address, attempt,
                  {"data_length", length,
                   "a single register takes 1, 2 or 4 bytes, or 8 at a doubleword offset "
                   "(two registers)"});
  const unsigned streaming = tx.get_streaming_width();
  if (streaming != 0 && streaming < length)
    return refuse(tlm::TLM_BURST_ERROR_RESPONSE, ErrorCause::burst, address, attempt,
                  {"streaming_width", streaming,
                   "the streaming width must be 0 or at least the data length: the registers "
                   "are not FIFOs"});
  if (row->words > 1 && !sub_word) {
    const std::uint32_t first = static_cast<std::uint32_t>(address - row->offset) / 4;
    if (first + length / 4 > row->words)  // the burst's tail is not mapped to this window
      return refuse(tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address,
                    std::uint64_t{row->end()}, attempt,
                    {"data_length", length, "a burst must end inside its window"});
  }
  if (const unsigned char* enables = tx.get_byte_enable_ptr();
      enables != nullptr && !all_bytes_enabled(enables, tx.get_byte_enable_length(), length))
    return refuse(tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE, ErrorCause::byte_enable, address, attempt,
                  {"byte_enable_ptr", tx.get_byte_enable_length(),
                   "byte enables must enable every byte (or be absent); use a shorter "
                   "access for part of a word"});
  if (attempt.command != tlm::TLM_READ_COMMAND && attempt.command != tlm::TLM_WRITE_COMMAND &&
      attempt.command != tlm::TLM_IGNORE_COMMAND)
    return refuse(tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCause::command, address, attempt,
                  {"command", static_cast<std::uint64_t>(attempt.command),
                   "the command must be read, write or ignore"});
  return tlm::TLM_OK_RESPONSE;
}

void SpecularTarget::b_transport(tlm::tlm_generic_payload& tx, sc_time& delay) {
  const Attempt attempt{tx.get_command(), tx.get_address(), tx.get_data_length()};
  const RegisterInfo* row = nullptr;
  if (const tlm::tlm_response_status checked = check_access(tx, attempt, row);
      checked != tlm::TLM_OK_RESPONSE)
    return tx.set_response_status(checked);
  if (attempt.command == tlm::TLM_IGNORE_COMMAND)
    return tx.set_response_status(tlm::TLM_OK_RESPONSE);
  if (attempt.length < 4)
    return tx.set_response_status(sub_word(*row, attempt, tx.get_data_ptr(), delay));
  if (row->words == 1 && attempt.length == 8)
    return tx.set_response_status(double_word(*row, attempt, tx.get_data_ptr(), delay));

  const std::uint32_t first = static_cast<std::uint32_t>(attempt.address - row->offset) / 4;
  const std::uint32_t words = attempt.length / 4;
  if (attempt.command == tlm::TLM_READ_COMMAND) {
    read(*row, first, words, tx.get_data_ptr());
    return tx.set_response_status(tlm::TLM_OK_RESPONSE);
  }
  if (row->access == Access::read_only)
    return tx.set_response_status(refuse(tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCause::read_only,
                                         attempt.address, attempt,
                                         {row->name, attempt.address, read_only_rule}));
  tx.set_response_status(
      write(*row, first, words, tx.get_data_ptr(), attempt.address, attempt, delay));
}

tlm::tlm_response_status SpecularTarget::sub_word(const RegisterInfo& row, const Attempt& attempt,
                                                  unsigned char* data, sc_time& delay) {
  const std::uint32_t index = static_cast<std::uint32_t>(attempt.address - row.offset) / 4;
  const unsigned lane = static_cast<unsigned>(attempt.address % 4);
  // The word as the bus sees it (host byte order, as whole-word accesses carry it);
  // the access takes or replaces bytes lane .. lane + length - 1 of it.
  unsigned char bytes[4];
  if (attempt.command == tlm::TLM_READ_COMMAND) {
    store(bytes, peek(row, index));
    std::memcpy(data, bytes + lane, attempt.length);
    return tlm::TLM_OK_RESPONSE;
  }
  if (row.access == Access::read_only)
    return refuse(tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCause::read_only, attempt.address,
                  attempt, {row.name, attempt.address, read_only_rule});
  if (!takes_sub_word_writes(row.reg))
    return refuse(tlm::TLM_BURST_ERROR_RESPONSE, ErrorCause::burst, attempt.address, attempt,
                  {row.name, attempt.length,
                   "windows take whole words only: each word feeds or starts an operation"});
  // STATUS (W1C) and CONTROL (self-clearing) see the bytes written and zeros
  // elsewhere; the operand registers keep their other bytes (read-modify-write).
  const bool merges = row.reg != Reg::status && row.reg != Reg::control;
  store(bytes, merges ? word(row.reg) : 0u);
  std::memcpy(bytes + lane, data, attempt.length);
  return write(row, 0, 1, bytes, attempt.address, attempt, delay);
}

tlm::tlm_response_status SpecularTarget::double_word(const RegisterInfo& row,
                                                     const Attempt& attempt, unsigned char* data,
                                                     sc_time& delay) {
  const std::uint64_t second_address = attempt.address + 4;
  const RegisterInfo* second = decode(second_address);
  if (second == nullptr)
    return refuse(tlm::TLM_ADDRESS_ERROR_RESPONSE, ErrorCause::address, second_address, attempt,
                  {"address", second_address,
                   "an 8-byte access covers two registers; its second word is a hole"});
  if (attempt.command == tlm::TLM_READ_COMMAND) {
    store(data, peek(row, 0));
    store(data + 4, peek(*second, 0));
    return tlm::TLM_OK_RESPONSE;
  }
  // All or nothing, as for a burst: both words are vetted before either is written.
  for (const auto& [r, address, offset] :
       {std::tuple{&row, attempt.address, 0u}, std::tuple{second, second_address, 4u}})
    if (const tlm::tlm_response_status verdict = vet_write(*r, load(data + offset), attempt, address);
        verdict != tlm::TLM_OK_RESPONSE)
      return verdict;
  const tlm::tlm_response_status first = write(row, 0, 1, data, attempt.address, attempt, delay);
  if (first != tlm::TLM_OK_RESPONSE) return first;
  return write(*second, 0, 1, data + 4, second_address, attempt, delay);
}

tlm::tlm_response_status SpecularTarget::vet_write(const RegisterInfo& row, std::uint32_t value,
                                                   const Attempt& attempt,
                                                   std::uint64_t address) {
  if (row.access == Access::read_only)
    return refuse(tlm::TLM_COMMAND_ERROR_RESPONSE, ErrorCause::read_only, address, attempt,
                  {row.name, address, read_only_rule});
  if (row.reg == Reg::status) return tlm::TLM_OK_RESPONSE;
  if (const ErrorCause cause = check_value(row.reg, value); cause != ErrorCause::none)
    return refuse(tlm::TLM_GENERIC_ERROR_RESPONSE, cause, address, attempt,
                  {row.name, value, describe(cause)});
  const bool acts = row.reg != Reg::control || (value & control_bits::start) != 0;
  if (acts && busy_)
    return refuse(tlm::TLM_GENERIC_ERROR_RESPONSE, ErrorCause::busy, address, attempt,
                  {row.name, value, describe(ErrorCause::busy)});
  return tlm::TLM_OK_RESPONSE;
}

const char* SpecularTarget::address_rule(std::uint64_t address) {
  return address >= map_size ? "the map decodes offsets below 0x8000 (map_size) only"
                             : "this offset is a hole in the register map";
}

tlm::tlm_response_status SpecularTarget::refuse(tlm::tlm_response_status status, ErrorCause cause,
                                                std::uint64_t address, const Attempt& attempt,
                                                const Why& why) {
  error_ = true;
  cause_ = cause;
  word(Reg::error_address) = address > 0xFFFFFFFFu ? error_address_beyond_32_bits
                                                   : static_cast<std::uint32_t>(address);
  report_refusal(status, cause, word(Reg::error_address), attempt, why);
  return status;
}

void SpecularTarget::report_refusal(tlm::tlm_response_status status, ErrorCause cause,
                                    std::uint32_t error_address, const Attempt& attempt,
                                    const Why& why) {
  // An integrator's first refused access must say why in the log, not only in STATUS
  // (which a refused STATUS read cannot show); once per cause keeps a fuzzer quiet.
  const std::uint32_t bit = 1u << static_cast<unsigned>(cause);
  if ((reported_causes_ & bit) == 0) {
    reported_causes_ |= bit;
    std::ostringstream s;
    s << name() << ": " << command_name(attempt.command) << " of " << attempt.length
      << " byte(s) at offset 0x" << std::hex << attempt.address << " refused with "
      << response_name(status) << ": " << why.field << " = 0x" << why.value << std::dec
      << " (" << why.value << "): " << why.rule << ". STATUS.error is set, cause "
      << to_string(cause) << " (" << static_cast<int>(cause) << "), ERROR_ADDRESS 0x" << std::hex
      << error_address << std::dec
      << "; later refusals with this cause set STATUS only (docs/integration.md)";
    SC_REPORT_WARNING(report::tlm_access_refused, s.str().c_str());
  }
}

// ---- reads -------------------------------------------------------------------------

std::uint32_t SpecularTarget::status_word() const {
  return (busy_ ? status_bits::busy : 0u) | (done_ ? status_bits::done : 0u) |
         (error_ ? status_bits::error : 0u) |
         (static_cast<std::uint32_t>(cause_) << status_bits::cause_shift);
}

std::uint32_t SpecularTarget::peek(const RegisterInfo& row, std::uint32_t index) const {
  switch (row.reg) {
    case Reg::status: return status_word();
    case Reg::control: return 0;  // START is self-clearing
    case Reg::operands: return peek(info(operand_register(index)), 0);
    case Reg::results: return word(result_register(index));
    case Reg::batch_cos: return batch_cos_[index];
    case Reg::batch_out: return batch_out_[index];
    default: return word(row.reg);
  }
}

void SpecularTarget::read(const RegisterInfo& row, std::uint32_t first, std::uint32_t words,
                          unsigned char* data) const {
  if (row.reg == Reg::batch_out)
    std::memcpy(data, &batch_out_[first], 4 * words);
  else if (row.reg == Reg::batch_cos)
    std::memcpy(data, &batch_cos_[first], 4 * words);
  else
    for (std::uint32_t i = 0; i < words; ++i) store(data + 4 * i, peek(row, first + i));
}

// ---- writes ------------------------------------------------------------------------

ErrorCause SpecularTarget::check_value(Reg reg, std::uint32_t value) const {
  // Which rule applies is the register map's value_check; the limits are the formats'.
  const ErrorCause rule = info(reg).value_check;
  switch (rule) {
    case ErrorCause::cos_out_of_range:
      return value > static_cast<std::uint64_t>(formats_.cos.one()) ? rule : ErrorCause::none;
    case ErrorCause::n_out_of_range:
      return (value < n_min || value > n_max) ? rule : ErrorCause::none;
    case ErrorCause::rgb_out_of_range:
      return value > static_cast<std::uint64_t>(formats_.rgb.max_code()) ? rule : ErrorCause::none;
    case ErrorCause::reserved_bits:
      return (value & ~control_bits::defined) ? rule : ErrorCause::none;
    default: return ErrorCause::none;
  }
}

tlm::tlm_response_status SpecularTarget::write(const RegisterInfo& row, std::uint32_t first,
                                               std::uint32_t words, const unsigned char* data,
                                               std::uint64_t address, const Attempt& attempt,
                                               sc_time& delay) {
  const auto busy = [&](std::uint64_t value) {
    return refuse(tlm::TLM_GENERIC_ERROR_RESPONSE, ErrorCause::busy, address, attempt,
                  {row.name, value, describe(ErrorCause::busy)});
  };
  switch (row.reg) {
    case Reg::status: {  // write 1 to clear
      const std::uint32_t value = load(data);
      if (value & status_bits::error) {
        error_ = false;
        cause_ = ErrorCause::none;
        word(Reg::error_address) = 0;
      }
      if ((value & status_bits::done) && done_) {
        done_ = false;
        irq_event_.notify(delay);
      }
      return tlm::TLM_OK_RESPONSE;
    }
    case Reg::control: {
      const std::uint32_t value = load(data);
      if (const ErrorCause cause = check_value(Reg::control, value); cause != ErrorCause::none)
        return refuse(tlm::TLM_GENERIC_ERROR_RESPONSE, cause, address, attempt,
                      {row.name, value, describe(cause)});
      if (value & control_bits::start) {
        if (busy_) return busy(value);
        run(&word(Reg::cos), 1, &word(Reg::out_r), delay);
      }
      return tlm::TLM_OK_RESPONSE;
    }
    case Reg::operands: {
      // Spec §3 protocol: registers 2, 10–12 hold still until 35 rises.
      if (busy_) return busy(load(data));
      // All or nothing, as one register write each would check them: nothing is
      // stored (and nothing starts) unless every word is acceptable.
      for (std::uint32_t i = 0; i < words; ++i) {
        const Reg reg = operand_register(first + i);
        const ErrorCause cause = check_value(reg, load(data + 4 * i));
        if (cause != ErrorCause::none)
          return refuse(tlm::TLM_GENERIC_ERROR_RESPONSE, cause, address + 4 * i, attempt,
                        {info(reg).name, load(data + 4 * i), describe(cause)});
      }
      bool start = false;
      for (std::uint32_t i = 0; i < words; ++i) {
        const Reg reg = operand_register(first + i);
        if (reg == Reg::control)
          start = (load(data + 4 * i) & control_bits::start) != 0;
        else
          word(reg) = load(data + 4 * i);
      }
      if (start) run(&word(Reg::cos), 1, &word(Reg::out_r), delay);
      return tlm::TLM_OK_RESPONSE;
    }
    case Reg::batch_cos: {
      if (busy_) return busy(load(data));
      // All or nothing: check every word before any is stored or computed.
      for (std::uint32_t i = 0; i < words; ++i)
        if (const ErrorCause cause = check_value(Reg::batch_cos, load(data + 4 * i));
            cause != ErrorCause::none)
          return refuse(tlm::TLM_GENERIC_ERROR_RESPONSE, cause, address + 4 * i, attempt,
                        {row.name, load(data + 4 * i), describe(cause)});
      std::memcpy(&batch_cos_[first], data, 4 * words);
      run(&batch_cos_[first], words, &batch_out_[3 * first], delay);
      return tlm::TLM_OK_RESPONSE;
    }
    default: {  // operand registers: plain storage, range-checked, never clamped
      // Spec §3 protocol: registers 2, 10–12 hold still until 35 rises.
      const std::uint32_t value = load(data);
      if (busy_) return busy(value);
      const ErrorCause cause = check_value(row.reg, value);
      if (cause != ErrorCause::none)
        return refuse(tlm::TLM_GENERIC_ERROR_RESPONSE, cause, address, attempt,
                      {row.name, value, describe(cause)});
      word(row.reg) = value;
      return tlm::TLM_OK_RESPONSE;
    }
  }
}

// ---- operations --------------------------------------------------------------------

void SpecularTarget::run(const std::uint32_t* cos, std::size_t count, std::uint32_t* out,
                         sc_time& delay) {
  Operands shared;
  shared.n = word(Reg::n);
  shared.rgb = {word(Reg::r), word(Reg::g), word(Reg::b)};

  busy_ = true;
  done_ = false;
  irq_event_.notify(delay);  // done_irq falls when the operation starts
  execute(shared, cos, count, out, last_, delay);
  if (meter_ && !charges_itself_) {
    Operands op = shared;
    for (std::size_t i = 0; i < count; ++i) {
      op.cos = cos[i];
      meter_->operation(config_, op);
    }
  }
  busy_ = false;
  done_ = true;
  done_at_ = sc_core::sc_time_stamp() + delay;
  irq_event_.notify(delay);  // ... and rises when it ends (drive_irq re-arms if needed)

  for (int ch = 0; ch < 3; ++ch) words_[index_of(Reg::out_r) + ch] = out[3 * (count - 1) + ch];
  word(Reg::reg1) = low_word(last_.reg1);
  word(Reg::reg9_pass1_lo) = low_word(last_.reg9_pass1);
  word(Reg::reg9_pass1_hi) = high_word(last_.reg9_pass1);
  word(Reg::reg9_pass2_lo) = low_word(last_.reg9_pass2);
  word(Reg::reg9_pass2_hi) = high_word(last_.reg9_pass2);
  word(Reg::rom38_k) = low_word(last_.rom38_k);
  word(Reg::norm39) = low_word(last_.norm39);
}

// ---- energy and power (docs/energy.md) ----------------------------------------------

void SpecularTarget::transport(tlm::tlm_generic_payload& tx, sc_time& delay) {
  b_transport(tx, delay);
  if (!meter_ || tx.get_response_status() != tlm::TLM_OK_RESPONSE) return;
  // A bus beat per word: AXI4-Lite carries 32 bits a transfer, and the IP's figures
  // are per transfer.
  const std::uint64_t beats = (tx.get_data_length() + 3) / 4;
  if (tx.get_command() == tlm::TLM_READ_COMMAND) meter_->reads(beats);
  else if (tx.get_command() == tlm::TLM_WRITE_COMMAND) meter_->writes(beats);
  if (power_window_ != sc_core::SC_ZERO_TIME) bin_energy(sc_core::sc_time_stamp() + delay);
}

double SpecularTarget::charged_pj() const {
  if (!meter_) return 0;
  const energy::EnergyTally t = meter_->tally(0);
  return t.total_pj();
}

energy::EnergyTally SpecularTarget::energy() const { return energy(sc_core::sc_time_stamp()); }

energy::EnergyTally SpecularTarget::energy(const sc_time& at) const {
  if (!meter_) return energy::EnergyTally{};
  return meter_->tally(at / period_);
}

void SpecularTarget::set_energy_model(bool on) {
  if (on && !meter_) meter_ = std::make_unique<energy::EnergyMeter>(calibration_, formats_);
  if (!on) meter_.reset();
  binned_pj_ = charged_pj();
}

void SpecularTarget::set_energy_calibration(energy::Calibration calibration) {
  calibration_ = calibration;
  if (meter_) meter_ = std::make_unique<energy::EnergyMeter>(calibration_, formats_);
  binned_pj_ = 0;
}

void SpecularTarget::trace_power(const sc_time& window) {
  if (window <= sc_core::SC_ZERO_TIME)
    throw std::invalid_argument("TLM target: power window " + window.to_string() + " must be positive");
  if (power_window_ != sc_core::SC_ZERO_TIME)
    throw std::invalid_argument("TLM target: the power trace is already on (window " +
                                power_window_.to_string() + ")");
  power_window_ = window;
  set_energy_model(true);  // a power trace needs the energy (and starts its binning there)
  power_on_.notify(sc_core::SC_ZERO_TIME);
}

void SpecularTarget::bin_energy(const sc_time& at) {
  const double now_pj = charged_pj();
  const double pj = now_pj - binned_pj_;
  binned_pj_ = now_pj;
  if (pj == 0) return;
  // power_bins_.front() is the window that starts at window_start_ (sample_power()
  // closes it next); energy annotated before it goes to it.
  const std::size_t index =
      at > window_start_ ? static_cast<std::size_t>(std::floor((at - window_start_) / power_window_)) : 0;
  if (power_bins_.size() <= index) power_bins_.resize(index + 1, 0.0);
  power_bins_[index] += pj;
}

void SpecularTarget::sample_power() {
  while (power_window_ == sc_core::SC_ZERO_TIME) sc_core::wait(power_on_);
  const double clocks_per_window = power_window_ / period_;
  window_start_ = sc_core::sc_time_stamp();
  for (;;) {
    sc_core::wait(power_window_);
    double pj = 0;
    if (meter_) pj = clocks_per_window * energy::bus_table.idle_clock_pj;
    if (!power_bins_.empty()) {
      if (meter_) pj += power_bins_.front();
      power_bins_.pop_front();
    }
    window_start_ += power_window_;
    energy_pj_ += pj;
    const double mw = pj / (power_window_.to_seconds() * 1e9);  // pJ / ns = mW
    power_mw_.write(mw);
    for (const auto& callback : power_callbacks_) callback(sc_core::sc_time_stamp(), mw);
  }
}

void SpecularTarget::trace(sc_core::sc_trace_file* file) const {
  const std::string scope = std::string(name()) + ".";
  sc_core::sc_trace(file, busy_, scope + "status_busy");
  sc_core::sc_trace(file, done_, scope + "status_done");
  sc_core::sc_trace(file, error_, scope + "status_error");
  sc_core::sc_trace(file, irq_level_, scope + "done_irq");
  sc_core::sc_trace(file, power_mw_, scope + "power_mw");
  sc_core::sc_trace(file, energy_pj_, scope + "energy_pj");
}

void SpecularTarget::rtl_done_irq(bool level, const sc_core::sc_time& delay) {
  done_ = level;
  if (level) done_at_ = sc_core::sc_time_stamp() + delay;
  irq_event_.notify(delay);
}

void SpecularTarget::drive_irq() {
  // Notifications keep only the earliest pending time, so this method recomputes the
  // level from the register state and re-arms itself for a rise still ahead.
  const sc_time now = sc_core::sc_time_stamp();
  bool level = done_;
  if (done_ && now < done_at_) {
    level = false;
    irq_event_.notify(done_at_ - now);
  }
  done_irq.write(level);
  if (level == irq_level_) return;
  irq_level_ = level;
  for (const auto& callback : irq_callbacks_) callback(level);
}

SpecularTarget::DefaultIrqBinding::DefaultIrqBinding(sc_core::sc_module_name name,
                                                     sc_core::sc_out<bool>& port)
    : sc_module(name), port(port), line("line") {}

void SpecularTarget::DefaultIrqBinding::before_end_of_elaboration() {
  // A platform that takes the interrupt by on_done_irq(), or not at all, need not
  // bind a signal: SystemC would stop elaboration with E109 (port not bound).
  if (port.bind_count() == 0) port.bind(line);
}

// ---- debug transport ---------------------------------------------------------------

bool SpecularTarget::poke(const RegisterInfo& row, std::uint32_t index, std::uint32_t value) {
  if (row.reg == Reg::operands)  // the storage behind it; CONTROL is not storage
    return poke(info(operand_register(index)), 0, value);
  if (row.access != Access::read_write || check_value(row.reg, value) != ErrorCause::none)
    return false;
  if (row.reg == Reg::batch_cos)
    batch_cos_[index] = value;
  else
    word(row.reg) = value;
  return true;
}

unsigned int SpecularTarget::transport_dbg(tlm::tlm_generic_payload& tx) {
  const std::uint64_t address = tx.get_address();
  const unsigned length = tx.get_data_length();
  unsigned char* data = tx.get_data_ptr();
  const tlm::tlm_command command = tx.get_command();
  if (address % 4 != 0 || length % 4 != 0) return 0;
  unsigned int bytes = 0;
  for (; bytes < length; bytes += 4) {
    const RegisterInfo* row = decode(address + bytes);
    if (row == nullptr) break;
    const std::uint32_t index = static_cast<std::uint32_t>(address + bytes - row->offset) / 4;
    if (command == tlm::TLM_READ_COMMAND) {
      store(data + bytes, peek(*row, index));
    } else if (command == tlm::TLM_WRITE_COMMAND) {
      if (!poke(*row, index, load(data + bytes))) break;
    } else {
      break;
    }
  }
  return bytes;
}

}  // namespace specular
