#include "bezcam/link/transport.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <modbus/modbus.h>

namespace bezcam::link {

std::string Endpoint::str() const {
  const bool v6 = host.find(':') != std::string::npos;
  return (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

// Accepts what people type: "host:port", "[v6]:port", ":port" and a bare
// port; the host defaults to loopback, the safe choice.
Endpoint parse_endpoint(std::string_view text, bool allow_zero) {
  const std::string shown(text);
  auto bad = [&](const std::string& why) -> InputError {
    return InputError(errc::link_endpoint, Place::at_file(shown),
                      "expected HOST:PORT (for example 127.0.0.1:5020); " + why);
  };
  Endpoint e;
  std::string_view port_text = text;
  if (!text.empty() && text.front() == '[') {  // [v6]:port
    const auto close = text.find(']');
    if (close == std::string_view::npos || close + 1 >= text.size() || text[close + 1] != ':')
      throw bad("an IPv6 address is written [ADDRESS]:PORT");
    e.host = std::string(text.substr(1, close - 1));
    port_text = text.substr(close + 2);
  } else if (const auto colon = text.rfind(':'); colon != std::string_view::npos) {
    if (text.find(':') != colon) throw bad("write an IPv6 address in brackets");
    if (colon > 0) e.host = std::string(text.substr(0, colon));
    port_text = text.substr(colon + 1);
  } else {
    throw bad("the port is missing (\"" + shown + ":5020\", for instance)");
  }
  if (e.host.empty()) throw bad("the host is empty");
  unsigned long port = 0;
  const auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (port_text.empty() || ec != std::errc() || end != port_text.data() + port_text.size())
    throw bad("the port \"" + std::string(port_text) + "\" is not a number");
  if (port > 65535 || (port == 0 && !allow_zero)) throw bad("the port must be between 1 and 65535");
  e.port = static_cast<std::uint16_t>(port);
  return e;
}

ModbusClient::ModbusClient(const Endpoint& to, std::chrono::milliseconds timeout) : to_(to) {
  const std::string service = std::to_string(to.port);
  // The _pi variant resolves host names and IPv6 as well as dotted quads.
  ctx_ = modbus_new_tcp_pi(to.host.c_str(), service.c_str());
  if (!ctx_)
    throw IoError(errc::link_connection, Place::at_file(to.str()),
                  std::string("cannot create a Modbus context: ") + std::strerror(errno));
  const auto ms = std::max<long long>(1, timeout.count());
  modbus_set_response_timeout(ctx_, static_cast<uint32_t>(ms / 1000), static_cast<uint32_t>((ms % 1000) * 1000));
  // A reply's bytes arrive together on TCP; the same bound per byte is generous.
  modbus_set_byte_timeout(ctx_, static_cast<uint32_t>(ms / 1000), static_cast<uint32_t>((ms % 1000) * 1000));
  // libmodbus bounds connect() by the response timeout too.
  if (modbus_connect(ctx_) == -1) {
    const int err = errno;
    modbus_free(ctx_);
    ctx_ = nullptr;
    throw IoError(errc::link_connection, Place::at_file(to.str()),
                  std::string("cannot connect: ") + modbus_strerror(err) +
                      "; is the controller running and listening on this address?");
  }
}

ModbusClient::~ModbusClient() { close(); }

void ModbusClient::close() {
  if (ctx_) {
    modbus_close(ctx_);
    modbus_free(ctx_);
    ctx_ = nullptr;
  }
}

// libmodbus reports an exception reply as errno MODBUS_ENOBASE + code; the
// controller answered, so the connection stays usable.
void ModbusClient::fail(const char* what) {
  const int err = errno;
  if (err > MODBUS_ENOBASE && err < MODBUS_ENOBASE + MODBUS_EXCEPTION_MAX)
    throw ModbusException(err - MODBUS_ENOBASE, std::string(what) + ": " + modbus_strerror(err));
  // Anything else leaves the stream in an unknown state: drop the socket.
  close();
  throw IoError(errc::link_connection, Place::at_file(to_.str()),
                std::string(what) + " failed: " + modbus_strerror(err));
}

namespace {
// The callers build requests from the register map's constants: a count
// out of range is a bug here, not something the controller should see.
void check_count(std::size_t n, std::size_t max, const Endpoint& to) {
  if (n == 0 || n > max)
    throw IoError(
        errc::link_request, Place::at_file(to.str()),
        "a request of " + std::to_string(n) + " registers is outside 1.." + std::to_string(max) + " (program bug)");
}
}  // namespace

void ModbusClient::read_holding(std::uint16_t addr, std::span<std::uint16_t> out) {
  if (!ctx_) throw IoError(errc::link_connection, Place::at_file(to_.str()), "the connection is closed");
  check_count(out.size(), MODBUS_MAX_READ_REGISTERS, to_);
  if (modbus_read_registers(ctx_, addr, static_cast<int>(out.size()), out.data()) == -1)
    fail("reading holding registers");
}

void ModbusClient::read_input(std::uint16_t addr, std::span<std::uint16_t> out) {
  if (!ctx_) throw IoError(errc::link_connection, Place::at_file(to_.str()), "the connection is closed");
  check_count(out.size(), MODBUS_MAX_READ_REGISTERS, to_);
  if (modbus_read_input_registers(ctx_, addr, static_cast<int>(out.size()), out.data()) == -1)
    fail("reading input registers");
}

void ModbusClient::write_register(std::uint16_t addr, std::uint16_t value) {
  if (!ctx_) throw IoError(errc::link_connection, Place::at_file(to_.str()), "the connection is closed");
  if (modbus_write_register(ctx_, addr, value) == -1) fail("writing a register");
}

void ModbusClient::write_registers(std::uint16_t addr, std::span<const std::uint16_t> values) {
  if (!ctx_) throw IoError(errc::link_connection, Place::at_file(to_.str()), "the connection is closed");
  check_count(values.size(), MODBUS_MAX_WRITE_REGISTERS, to_);
  if (modbus_write_registers(ctx_, addr, static_cast<int>(values.size()), values.data()) == -1)
    fail("writing registers");
}

void ModbusClient::write_and_read(std::uint16_t waddr, std::span<const std::uint16_t> values, std::uint16_t raddr,
                                  std::span<std::uint16_t> out) {
  if (!ctx_) throw IoError(errc::link_connection, Place::at_file(to_.str()), "the connection is closed");
  check_count(values.size(), MODBUS_MAX_WR_WRITE_REGISTERS, to_);
  check_count(out.size(), MODBUS_MAX_WR_READ_REGISTERS, to_);
  if (modbus_write_and_read_registers(ctx_, waddr, static_cast<int>(values.size()), values.data(), raddr,
                                      static_cast<int>(out.size()), out.data()) == -1)
    fail("writing and reading registers");
}

TransportFactory modbus_transport(const Endpoint& to) {
  return [to](std::chrono::milliseconds timeout) -> std::unique_ptr<Transport> {
    return std::make_unique<ModbusClient>(to, timeout);
  };
}

}  // namespace bezcam::link
