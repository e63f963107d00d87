#pragma once
/// Modbus TCP client side of the link: a thin RAII wrapper over libmodbus
/// that turns its errno conventions into typed errors.
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "bezcam/error.hpp"

typedef struct _modbus modbus_t;

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

/// One Modbus TCP connection (unit id 1). Every failure other than an
/// exception reply (refused or lost connection, timeout, garbled reply)
/// throws IoError("link.connection", endpoint, ...): the connection is then
/// unusable and must be replaced, since a late reply could otherwise be
/// taken for the answer to the next request.
class ModbusClient {
 public:
  /// Connects within `timeout`, which is also each request's response
  /// timeout. Throws IoError when the controller cannot be reached.
  ModbusClient(const Endpoint& to, std::chrono::milliseconds timeout);
  ~ModbusClient();
  ModbusClient(const ModbusClient&) = delete;
  ModbusClient& operator=(const ModbusClient&) = delete;

  /// FC 03.
  void read_holding(std::uint16_t addr, std::span<std::uint16_t> out);
  /// FC 04.
  void read_input(std::uint16_t addr, std::span<std::uint16_t> out);
  /// FC 06.
  void write_register(std::uint16_t addr, std::uint16_t value);
  /// FC 16.
  void write_registers(std::uint16_t addr, std::span<const std::uint16_t> values);
  /// FC 23: writes, then reads, in one transaction.
  void write_and_read(std::uint16_t waddr, std::span<const std::uint16_t> values, std::uint16_t raddr,
                      std::span<std::uint16_t> out);

  const Endpoint& endpoint() const { return to_; }
  /// Closes the socket (further calls throw IoError).
  void close();

 private:
  [[noreturn]] void fail(const char* what);
  Endpoint to_;
  modbus_t* ctx_ = nullptr;
};

}  // namespace bezcam::link
