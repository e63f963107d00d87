#include "bezcam/sim/in_process_transport.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "bezcam/error.hpp"

namespace bezcam::sim {

namespace {

constexpr const char* kPeer = "in-process";

// Removes `n` from `list` and says whether it was there (each fault fires once).
bool fires(std::vector<std::uint64_t>& list, std::uint64_t n) {
  const auto it = std::find(list.begin(), list.end(), n);
  if (it == list.end()) return false;
  list.erase(it);
  return true;
}

// Builds Modbus TCP frames exactly as they travel on the wire, so the
// controller's frame parsing is exercised as well, not bypassed.
class Frame {
 public:
  explicit Frame(std::uint8_t fc) : bytes_{0, 1, 0, 0, 0, 0, 1, fc} {}
  void u16(std::uint16_t v) {
    bytes_.push_back(static_cast<std::uint8_t>(v >> 8));
    bytes_.push_back(static_cast<std::uint8_t>(v & 0xFF));
  }
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  // Sets the MBAP length (unit id + PDU) once the frame is complete.
  std::span<const std::uint8_t> done() {
    const auto len = static_cast<std::uint16_t>(bytes_.size() - 6);
    bytes_[4] = static_cast<std::uint8_t>(len >> 8);
    bytes_[5] = static_cast<std::uint8_t>(len & 0xFF);
    return bytes_;
  }

 private:
  std::vector<std::uint8_t> bytes_;
};

class InProcessTransport final : public link::Transport {
 public:
  explicit InProcessTransport(std::shared_ptr<InProcessLink::Shared> s) : s_(std::move(s)) {
    std::lock_guard lk(s_->m);
    const int attempt = ++s_->stats.connects;
    const auto& fails = s_->faults.failed_connects;
    if (std::find(fails.begin(), fails.end(), attempt) != fails.end())
      throw IoError(errc::link_connection, Place::at_file(kPeer), "cannot connect: refused by fault injection");
    id_ = s_->ctl.connection_opened();
    ++s_->stats.open;
  }
  ~InProcessTransport() override { close(); }

  void read_holding(std::uint16_t addr, std::span<std::uint16_t> out) override { read(3, addr, out); }
  void read_input(std::uint16_t addr, std::span<std::uint16_t> out) override { read(4, addr, out); }

  void write_register(std::uint16_t addr, std::uint16_t value) override {
    Frame f(6);
    f.u16(addr);
    f.u16(value);
    request(f.done(), {});
  }

  void write_registers(std::uint16_t addr, std::span<const std::uint16_t> values) override {
    Frame f(16);
    f.u16(addr);
    f.u16(static_cast<std::uint16_t>(values.size()));
    f.u8(static_cast<std::uint8_t>(2 * values.size()));
    for (const auto v : values) f.u16(v);
    request(f.done(), {});
  }

  void write_and_read(std::uint16_t waddr, std::span<const std::uint16_t> values, std::uint16_t raddr,
                      std::span<std::uint16_t> out) override {
    Frame f(23);
    f.u16(raddr);
    f.u16(static_cast<std::uint16_t>(out.size()));
    f.u16(waddr);
    f.u16(static_cast<std::uint16_t>(values.size()));
    f.u8(static_cast<std::uint8_t>(2 * values.size()));
    for (const auto v : values) f.u16(v);
    request(f.done(), out);
  }

  void close() override {
    if (id_ == 0) return;
    std::lock_guard lk(s_->m);
    s_->ctl.connection_closed(id_);
    --s_->stats.open;
    id_ = 0;
  }

 private:
  void read(std::uint8_t fc, std::uint16_t addr, std::span<std::uint16_t> out) {
    Frame f(fc);
    f.u16(addr);
    f.u16(static_cast<std::uint16_t>(out.size()));
    request(f.done(), out);
  }

  // One round trip: faults, the controller's answer, and its translation
  // into the Transport contract (exception reply, lost connection, values).
  void request(std::span<const std::uint8_t> adu, std::span<std::uint16_t> out) {
    if (id_ == 0) throw IoError(errc::link_connection, Place::at_file(kPeer), "the connection is closed");
    FrameReply r;
    bool lost = false;
    {
      std::lock_guard lk(s_->m);
      const std::uint64_t n = ++s_->stats.requests;
      if (fires(s_->faults.drop_before, n)) {
        lost = true;
      } else {
        r = s_->ctl.handle_frame(id_, adu);
        lost = r.drop || fires(s_->faults.drop_after, n);
      }
    }
    if (lost) {
      close();
      throw IoError(errc::link_connection, Place::at_file(kPeer), "the connection was dropped");
    }
    if (r.exception != 0) throw link::ModbusException(r.exception, "Modbus exception " + std::to_string(r.exception));
    if (r.regs.size() != out.size()) {
      close();
      throw IoError(errc::link_connection, Place::at_file(kPeer), "a reply of the wrong length");
    }
    std::copy(r.regs.begin(), r.regs.end(), out.begin());
  }

  std::shared_ptr<InProcessLink::Shared> s_;
  ConnId id_ = 0;
};

}  // namespace

InProcessLink::InProcessLink(SimController& controller, LinkFaults faults)
    : shared_(std::make_shared<Shared>(controller, std::move(faults))) {}

link::TransportFactory InProcessLink::factory() const {
  return [s = shared_](std::chrono::milliseconds) -> std::unique_ptr<link::Transport> {
    return std::make_unique<InProcessTransport>(s);
  };
}

std::unique_ptr<link::Transport> InProcessLink::connect() const {
  return std::make_unique<InProcessTransport>(shared_);
}

LinkStats InProcessLink::stats() const {
  std::lock_guard lk(shared_->m);
  return shared_->stats;
}

}  // namespace bezcam::sim
