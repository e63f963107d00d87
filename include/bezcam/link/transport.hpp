#pragma once
/// Client side of the link: the register operations the sender needs
/// (Transport), and their Modbus TCP implementation, a thin RAII wrapper
/// over libmodbus that turns its errno conventions into typed errors.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "bezcam/error.hpp"

typedef struct _modbus modbus_t;  // NOLINT(bugprone-reserved-identifier): libmodbus names its type so

namespace bezcam::link {

/// Where a controller listens.
struct Endpoint {
  std::string host = "127.0.0.1";
  std::uint16_t port = 502;
  /// "host:port" ("[v6]:port" for IPv6 literals).
  std::string str() const;
};

/// Parses "HOST:PORT", "[IPV6]:PORT", ":PORT" or "PORT" (host 127.0.0.1).
/// Port 0 is accepted only with `allow_zero` (a server asking the system
/// for a free port). Throws InputError("link.endpoint", ...).
Endpoint parse_endpoint(std::string_view text, bool allow_zero = false);

/// The controller answered with a Modbus exception (it is alive and refused
/// the request). `code` is the exception code (1 illegal function, 2 illegal
/// address, 3 illegal value, 4 device failure, 6 busy).
class ModbusException : public std::runtime_error {
 public:
  ModbusException(int code, const std::string& what) : std::runtime_error(what), code_(code) {}
  int code() const noexcept { return code_; }

 private:
  int code_;
};

/// One connection to a controller: the register operations of
/// docs/modbus-register-map.md. A reply refusing the request (the controller
/// is alive and said no) throws ModbusException; every other failure (lost
/// connection, timeout, garbled reply) throws IoError("link.connection",
/// ...) and leaves the connection unusable: it must be replaced, since a
/// late reply could otherwise be taken for the answer to the next request.
class Transport {
 public:
  virtual ~Transport() = default;

  /// FC 03.
  virtual void read_holding(std::uint16_t addr, std::span<std::uint16_t> out) = 0;
  /// FC 04.
  virtual void read_input(std::uint16_t addr, std::span<std::uint16_t> out) = 0;
  /// FC 06.
  virtual void write_register(std::uint16_t addr, std::uint16_t value) = 0;
  /// FC 16.
  virtual void write_registers(std::uint16_t addr, std::span<const std::uint16_t> values) = 0;
  /// FC 23: writes, then reads, in one transaction.
  virtual void write_and_read(std::uint16_t waddr, std::span<const std::uint16_t> values, std::uint16_t raddr,
                              std::span<std::uint16_t> out) = 0;
  /// Closes the connection (further calls throw IoError). Idempotent.
  virtual void close() = 0;
};

/// Opens a new connection whose requests time out after `timeout` (which
/// also bounds the connection itself). Throws IoError when the controller
/// cannot be reached. The sender calls it once at the start and once per
/// reconnection attempt.
using TransportFactory = std::function<std::unique_ptr<Transport>(std::chrono::milliseconds timeout)>;

/// One Modbus TCP connection (unit id 1), with the error contract of
/// Transport.
class ModbusClient final : public Transport {
 public:
  /// Connects within `timeout`, which is also each request's response
  /// timeout. Throws IoError when the controller cannot be reached.
  ModbusClient(const Endpoint& to, std::chrono::milliseconds timeout);
  ~ModbusClient() override;
  ModbusClient(const ModbusClient&) = delete;
  ModbusClient& operator=(const ModbusClient&) = delete;

  void read_holding(std::uint16_t addr, std::span<std::uint16_t> out) override;
  void read_input(std::uint16_t addr, std::span<std::uint16_t> out) override;
  void write_register(std::uint16_t addr, std::uint16_t value) override;
  void write_registers(std::uint16_t addr, std::span<const std::uint16_t> values) override;
  void write_and_read(std::uint16_t waddr, std::span<const std::uint16_t> values, std::uint16_t raddr,
                      std::span<std::uint16_t> out) override;

  const Endpoint& endpoint() const { return to_; }
  /// Closes the socket (further calls throw IoError).
  void close() override;

 private:
  [[noreturn]] void fail(const char* what);
  Endpoint to_;
  modbus_t* ctx_ = nullptr;
};

/// A factory of ModbusClient connections to `to`.
TransportFactory modbus_transport(const Endpoint& to);

}  // namespace bezcam::link
