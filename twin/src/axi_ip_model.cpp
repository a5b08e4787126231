// The verilated IP (kept apart from SystemC's headers: Verilator's verilated_funcs.h
// reads sc_time_stamp() when SystemC is included first).
#include "axi_ip_model.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Vspecular_ip_axi_fast.h"
#include "Vspecular_ip_axi_fast___024root.h"
#include "rom_loader.h"
#include "thread_context_guard.h"

namespace specular {

namespace {
constexpr std::uint32_t axi_slverr = 2;
constexpr std::uint64_t transfer_cycle_limit = 64;  // no transfer of the IP takes more
}  // namespace

/// The verilated IP and its clock: one AXI4-Lite transfer at a time, as master.
class AxiIpModel::Impl {
 public:
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() { context_guard_.enter(); }
  explicit Impl(const Config& config) {
    const RomImages& images = rom_images_once(Formats(config.widths));
    write_rom_words(top_.rootp->specular_ip_axi__DOT__device__DOT__rom5__DOT__mantissa_rom, images.rom5, "ROM 5");
    write_rom_words(top_.rootp->specular_ip_axi__DOT__device__DOT__rom38__DOT__k_rom, images.rom38, "ROM 38");
    top_.aresetn = 0;
    for (int i = 0; i < 2; ++i) edge();
    top_.aresetn = 1;
    top_.eval();
    cycles_ = 0;
  }

  /// From now on the master stalls at random (seeded): AWVALID, WVALID and ARVALID rise
  /// 0-3 cycles late, each independently, and BREADY and RREADY are low in a cycle with
  /// `percent` % chance. 0 %: no stall (the timing of docs/rtl_ip.md).
  void stall_at_random(std::uint32_t seed, unsigned percent) {
    random_ = seed == 0 ? 1 : seed;
    stall_percent_ = percent;
  }

  /// One write transfer; returns BRESP and adds the cycles it took.
  std::uint32_t write(std::uint32_t address, std::uint32_t data, std::uint32_t strobes) {
    top_.s_axi_awaddr = address;
    top_.s_axi_wdata = data;
    top_.s_axi_wstrb = strobes & 0xFu;
    unsigned aw_wait = valid_delay(), w_wait = valid_delay();
    bool aw_taken = false, w_taken = false, b_waiting = false;
    std::uint32_t b_seen = 0;
    for (std::uint64_t n = 0; n < transfer_cycle_limit; ++n) {
      top_.s_axi_awvalid = !aw_taken && aw_wait == 0;
      top_.s_axi_wvalid = !w_taken && w_wait == 0;
      top_.s_axi_bready = ready();
      top_.eval();
      const bool aw_fire = top_.s_axi_awvalid && top_.s_axi_awready;
      const bool w_fire = top_.s_axi_wvalid && top_.s_axi_wready;
      const bool b_valid = top_.s_axi_bvalid;
      const bool b_fire = b_valid && top_.s_axi_bready;
      const std::uint32_t resp = top_.s_axi_bresp;
      // The slave's side of the handshake, checked every cycle (docs/rtl_ip.md, "The protocol proven").
      if (b_valid && !(aw_taken && w_taken)) violation("AXI4-Lite: B before its AW and W were taken");
      if (b_waiting && !b_valid) violation("AXI4-Lite: BVALID dropped before BREADY");
      if (b_waiting && b_valid && resp != b_seen) violation("AXI4-Lite: BRESP changed while BVALID waited");
      edge();
      if (aw_fire) aw_taken = true;
      else if (aw_wait > 0) --aw_wait;
      if (w_fire) w_taken = true;
      else if (w_wait > 0) --w_wait;
      if (b_fire) {
        top_.s_axi_awvalid = 0;
        top_.s_axi_wvalid = 0;
        top_.s_axi_bready = 0;
        check_resp(resp, "BRESP");
        return resp;
      }
      b_waiting = b_valid;
      b_seen = resp;
    }
    violation("AXI4-Lite: no write response within 64 cycles");
    return axi_slverr;
  }

  /// One read transfer; returns RRESP, the data in `data`, and adds the cycles it took.
  std::uint32_t read(std::uint32_t address, std::uint32_t& data) {
    top_.s_axi_araddr = address;
    unsigned ar_wait = valid_delay();
    bool ar_taken = false, r_waiting = false;
    std::uint32_t r_seen = 0, data_seen = 0;
    for (std::uint64_t n = 0; n < transfer_cycle_limit; ++n) {
      top_.s_axi_arvalid = !ar_taken && ar_wait == 0;
      top_.s_axi_rready = ready();
      top_.eval();
      const bool ar_fire = top_.s_axi_arvalid && top_.s_axi_arready;
      const bool r_valid = top_.s_axi_rvalid;
      const bool r_fire = r_valid && top_.s_axi_rready;
      const std::uint32_t resp = top_.s_axi_rresp;
      data = top_.s_axi_rdata;
      if (r_valid && !ar_taken) violation("AXI4-Lite: R before its AR was taken");
      if (r_waiting && !r_valid) violation("AXI4-Lite: RVALID dropped before RREADY");
      if (r_waiting && r_valid && (resp != r_seen || data != data_seen))
        violation("AXI4-Lite: RRESP or RDATA changed while RVALID waited");
      edge();
      if (ar_fire) ar_taken = true;
      else if (ar_wait > 0) --ar_wait;
      if (r_fire) {
        top_.s_axi_arvalid = 0;
        top_.s_axi_rready = 0;
        check_resp(resp, "RRESP");
        return resp;
      }
      r_waiting = r_valid;
      r_seen = resp;
      data_seen = data;
    }
    violation("AXI4-Lite: no read response within 64 cycles");
    return axi_slverr;
  }

  /// The first handshake rule broken since the last call, or "" (then cleared).
  std::string take_violation() {
    std::string first;
    first.swap(violation_);
    return first;
  }
  bool done_irq() const { return top_.done_irq != 0; }
  std::uint64_t cycles() const { return cycles_; }
  /// Every change of done_irq since the last call: (cycle count, new level).
  std::vector<std::pair<std::uint64_t, bool>> take_irq_edges() {
    std::vector<std::pair<std::uint64_t, bool>> edges;
    edges.swap(irq_edges_);
    return edges;
  }

 private:
  /// xorshift32: a draw of the stalls (no state shared with anything else).
  std::uint32_t draw() {
    random_ ^= random_ << 13;
    random_ ^= random_ >> 17;
    random_ ^= random_ << 5;
    return random_;
  }
  unsigned valid_delay() { return stall_percent_ == 0 ? 0u : draw() % 4u; }
  bool ready() { return stall_percent_ == 0 || draw() % 100u >= stall_percent_; }
  void edge() {
    top_.aclk = 0;
    top_.eval();
    top_.aclk = 1;
    top_.eval();
    ++cycles_;
    if ((top_.done_irq != 0) != irq_) {
      irq_ = top_.done_irq != 0;
      irq_edges_.emplace_back(cycles_, irq_);
    }
  }
  void violation(const std::string& what) {
    if (violation_.empty()) violation_ = what;
  }
  void check_resp(std::uint32_t resp, const char* channel) {
    if (resp == 1)  // EXOKAY: not legal on AXI4-Lite
      violation(std::string("AXI4-Lite: ") + channel + " EXOKAY");
  }

  VerilatedContext context_;
  ThreadContextGuard context_guard_{context_};  // between the two: thread_context_guard.h
  Vspecular_ip_axi_fast top_{&context_};
  std::uint64_t cycles_ = 0;
  std::vector<std::pair<std::uint64_t, bool>> irq_edges_;
  bool irq_ = false;
  std::uint32_t random_ = 1;
  unsigned stall_percent_ = 0;
  std::string violation_;
};

AxiIpModel::AxiIpModel(const Config& config) : impl_(std::make_unique<Impl>(config)) {}
AxiIpModel::~AxiIpModel() = default;
std::uint32_t AxiIpModel::write(std::uint32_t address, std::uint32_t data, std::uint32_t strobes) {
  return impl_->write(address, data, strobes);
}
std::uint32_t AxiIpModel::read(std::uint32_t address, std::uint32_t& data) { return impl_->read(address, data); }
std::string AxiIpModel::take_violation() { return impl_->take_violation(); }
bool AxiIpModel::done_irq() const { return impl_->done_irq(); }
std::uint64_t AxiIpModel::cycles() const { return impl_->cycles(); }
std::vector<std::pair<std::uint64_t, bool>> AxiIpModel::take_irq_edges() { return impl_->take_irq_edges(); }
void AxiIpModel::stall_at_random(std::uint32_t seed, unsigned percent) { impl_->stall_at_random(seed, percent); }

}  // namespace specular
