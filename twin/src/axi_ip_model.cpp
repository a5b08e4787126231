// The verilated IP (kept apart from SystemC's headers: Verilator's verilated_funcs.h
// reads sc_time_stamp() when SystemC is included first).
#include "axi_ip_model.h"

#include <memory>
#include <string>

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

  /// One write transfer; returns BRESP and adds the cycles it took.
  std::uint32_t write(std::uint32_t address, std::uint32_t data, std::uint32_t strobes) {
    top_.s_axi_awaddr = address;
    top_.s_axi_wdata = data;
    top_.s_axi_wstrb = strobes & 0xFu;
    top_.s_axi_awvalid = 1;
    top_.s_axi_wvalid = 1;
    top_.s_axi_bready = 1;
    for (std::uint64_t n = 0; n < transfer_cycle_limit; ++n) {
      top_.eval();
      const bool aw_fire = top_.s_axi_awvalid && top_.s_axi_awready;
      const bool w_fire = top_.s_axi_wvalid && top_.s_axi_wready;
      const bool b_fire = top_.s_axi_bvalid && top_.s_axi_bready;
      const std::uint32_t resp = top_.s_axi_bresp;
      if (b_fire && (top_.s_axi_awvalid || top_.s_axi_wvalid))
        violation("AXI4-Lite: B before its AW and W were taken");
      edge();
      if (aw_fire) top_.s_axi_awvalid = 0;
      if (w_fire) top_.s_axi_wvalid = 0;
      if (b_fire) {
        top_.s_axi_bready = 0;
        check_resp(resp, "BRESP");
        return resp;
      }
    }
    violation("AXI4-Lite: no write response within 64 cycles");
    return axi_slverr;
  }

  /// One read transfer; returns RRESP, the data in `data`, and adds the cycles it took.
  std::uint32_t read(std::uint32_t address, std::uint32_t& data) {
    top_.s_axi_araddr = address;
    top_.s_axi_arvalid = 1;
    top_.s_axi_rready = 1;
    for (std::uint64_t n = 0; n < transfer_cycle_limit; ++n) {
      top_.eval();
      const bool ar_fire = top_.s_axi_arvalid && top_.s_axi_arready;
      const bool r_fire = top_.s_axi_rvalid && top_.s_axi_rready;
      const std::uint32_t resp = top_.s_axi_rresp;
      data = top_.s_axi_rdata;
      if (r_fire && top_.s_axi_arvalid)
        violation("AXI4-Lite: R before its AR was taken");
      edge();
      if (ar_fire) top_.s_axi_arvalid = 0;
      if (r_fire) {
        top_.s_axi_rready = 0;
        check_resp(resp, "RRESP");
        return resp;
      }
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
  /// The cycle count when done_irq last changed, and its level then.
  std::uint64_t irq_changed_at() const { return irq_changed_at_; }

 private:
  void edge() {
    top_.aclk = 0;
    top_.eval();
    top_.aclk = 1;
    top_.eval();
    ++cycles_;
    if ((top_.done_irq != 0) != irq_) {
      irq_ = top_.done_irq != 0;
      irq_changed_at_ = cycles_;
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
  std::uint64_t irq_changed_at_ = 0;
  bool irq_ = false;
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
std::uint64_t AxiIpModel::irq_changed_at() const { return impl_->irq_changed_at(); }

}  // namespace specular
