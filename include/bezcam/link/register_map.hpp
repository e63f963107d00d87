#pragma once
/// The Modbus register map of the bezcam program link, shared by the sender
/// (streamer) and the controller (sim_controller). docs/modbus-register-map.md
/// is the prose version of this file, for PLC programmers.
///
/// Conventions (all of them are Modbus's own):
/// - addresses are PDU addresses (0-based; "register 40001" is address 0);
/// - a register is 16 bits, sent high byte first;
/// - a 32-bit value occupies two consecutive registers, high word first
///   ("big-endian word order", mbpoll -B);
/// - text is packed two bytes per register, the first byte in the high
///   byte; an odd length leaves the last low byte 0.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace bezcam::link {

/// Register 0 reads 0x425A ("BZ") on every bezcam controller.
inline constexpr std::uint16_t kMagic = 0x425A;
/// Incremented on any incompatible change to this map.
inline constexpr std::uint16_t kProtocolVersion = 1;

/// Register addresses.
namespace reg {
// --- Status block: read-only; FC 03 (holding) and FC 04 (input) read the
// same values at the same addresses.
inline constexpr std::uint16_t magic = 0;             ///< 0x425A
inline constexpr std::uint16_t version = 1;           ///< kProtocolVersion
inline constexpr std::uint16_t buffer_capacity = 2;   ///< receive buffer size, bytes
inline constexpr std::uint16_t max_chunk = 3;         ///< largest chunk payload, bytes
inline constexpr std::uint16_t session = 4;           ///< u32: current transfer's id, 0 none
inline constexpr std::uint16_t state = 6;             ///< State
inline constexpr std::uint16_t alarm = 7;             ///< Alarm
inline constexpr std::uint16_t alarm_line = 8;        ///< u32: program line of the alarm, 0 none
inline constexpr std::uint16_t ack_seq = 10;          ///< u32: last chunk sequence number applied
inline constexpr std::uint16_t ack_bytes = 12;        ///< u32: program bytes accepted so far
inline constexpr std::uint16_t buffer_free = 14;      ///< bytes the next chunk may carry
inline constexpr std::uint16_t last_reject = 15;      ///< Reject: why this connection's last request was refused
inline constexpr std::uint16_t lines_executed = 16;   ///< u32
inline constexpr std::uint16_t blocks_executed = 18;  ///< u32: motion blocks completed
inline constexpr std::uint16_t program_crc = 20;      ///< u32: CRC-32 of the bytes accepted so far
inline constexpr std::uint16_t pos_x = 22;            ///< i32: thousandths of the program unit
inline constexpr std::uint16_t pos_y = 24;            ///< i32
inline constexpr std::uint16_t pos_z = 26;            ///< i32
inline constexpr std::uint16_t feed = 28;             ///< u32: tenths of a program unit per minute
inline constexpr std::uint16_t spindle_rpm = 30;      ///< u32
inline constexpr std::uint16_t flags = 32;            ///< Flags bits
inline constexpr std::uint16_t tool = 33;             ///< current tool number
inline constexpr std::uint16_t motion = 34;           ///< modal motion 0..3 (G00..G03), 0xFFFF none
inline constexpr std::uint16_t connections = 35;      ///< open Modbus connections
inline constexpr std::uint16_t duplicates = 36;       ///< u32: retransmitted chunks acknowledged again
inline constexpr std::uint16_t rejects = 38;          ///< u32: requests refused (all connections)
inline constexpr std::uint16_t total_bytes = 40;      ///< u32: size announced by OPEN, 0 unknown
inline constexpr std::uint16_t starved_ms = 42;       ///< u32: machine time stood waiting for program data (ms)
inline constexpr std::uint16_t stalls = 44;           ///< u32: times the machine ran dry mid-program
inline constexpr std::uint16_t status_count = 48;     ///< 46..47 reserved (read 0)
// --- Text, read-only, same FC 03 / FC 04 rule.
inline constexpr std::uint16_t alarm_text = 64;  ///< 128 bytes: the alarm's message, NUL padded
inline constexpr std::uint16_t alarm_text_count = 64;
inline constexpr std::uint16_t machine_name = 128;  ///< 32 bytes: the profile's name, NUL padded
inline constexpr std::uint16_t machine_name_count = 16;
/// Registers [0, readable_end) can be read; nothing else can.
inline constexpr std::uint16_t readable_end = 144;
// --- Command block: write-only (FC 16, FC 23's write part; FC 06 for RESET).
inline constexpr std::uint16_t command = 0x100;
// --- Chunk window: write-only (FC 16 or FC 23's write part), always
// written from its first register: a 7-register header then the payload.
inline constexpr std::uint16_t chunk = 0x200;
inline constexpr std::uint16_t chunk_header = 7;  ///< session(2) seq(2) length(1) crc(2)
/// Payload registers in one chunk: FC 23 writes at most 121 registers.
inline constexpr std::uint16_t chunk_data_max = 121 - chunk_header;
}  // namespace reg

/// Largest payload of one chunk, bytes (228).
inline constexpr std::uint16_t kMaxChunkBytes = 2 * reg::chunk_data_max;

/// Controller state (register 6).
enum class State : std::uint16_t {
  idle = 0,       ///< no program since start-up or RESET
  receiving = 1,  ///< transfer open: receiving and executing (drip feed)
  finishing = 2,  ///< COMMIT accepted (length and CRC-32 confirmed); executing the rest
  done = 3,       ///< every line executed; the program is complete
  alarm = 4,      ///< stopped; see alarm, alarm_line, alarm_text
};

/// Why the controller stopped (register 7).
enum class Alarm : std::uint16_t {
  none = 0,
  gcode = 1,            ///< a line cannot be executed (syntax, unsupported word, bad NURBS block)
  travel_limit = 2,     ///< a move leaves the profile's travel
  feed_limit = 3,       ///< a feed above the profile's maximum
  line_too_long = 4,    ///< a line longer than the receive buffer
  crc_mismatch = 5,     ///< COMMIT's CRC-32 differs from the bytes received
  length_mismatch = 6,  ///< COMMIT's byte count differs from the bytes received
  incomplete = 7,       ///< the program ended inside a multi-line block
  sender_lost = 8,      ///< the owner was silent longer than the session timeout
  aborted = 9,          ///< ABORT command
};

/// Why a request was refused (register 15, per connection; the Modbus
/// exception code is the coarse version).
enum class Reject : std::uint16_t {
  none = 0,
  bad_function = 1,    ///< function code other than 03, 04, 06, 16, 23 (exception 01)
  bad_address = 2,     ///< outside the map, or the wrong block for the function (02)
  read_only = 3,       ///< write to the status or text registers (02)
  bad_count = 4,       ///< register count or byte count out of range (03)
  bad_command = 5,     ///< unknown command code or wrong number of arguments (03)
  busy = 6,            ///< another sender owns the open transfer (06)
  not_owner = 7,       ///< chunk from a connection that did not OPEN or RESUME (06)
  bad_token = 8,       ///< token does not match the transfer's owner (03)
  bad_session = 9,     ///< session id does not match the open transfer (03)
  not_receiving = 10,  ///< no open transfer (04)
  in_alarm = 11,       ///< the controller is in alarm; RESET or OPEN a new program (04)
  seq_gap = 12,        ///< sequence number beyond last acknowledged + 1 (03)
  bad_length = 13,     ///< chunk length 0, above max_chunk, or not matching the registers (03)
  bad_chunk_crc = 14,  ///< chunk CRC-32 does not match its payload (03)
  nul_byte = 15,       ///< payload holds a NUL byte (03)
  buffer_full = 16,    ///< payload larger than buffer_free; retry later (06)
  dup_mismatch = 17,   ///< a retransmitted chunk differs from the one applied (03)
};

/// Command codes (register 0x100); arguments follow in 0x101...
enum class Command : std::uint16_t {
  open = 1,    ///< token(u32) total_bytes(u32): start a new transfer
  resume = 2,  ///< token(u32) session(u32): re-attach after a reconnection
  commit = 3,  ///< token(u32) session(u32) total_bytes(u32) crc32(u32): end of program
  abort = 4,   ///< token(u32) session(u32): stop the transfer (alarm "aborted")
  reset = 5,   ///< no argument: clear DONE or ALARM back to IDLE (refused while a transfer is open)
};
/// Registers a command occupies including its code (the write must be exact).
std::uint16_t command_length(Command c);

/// Bits of register 32.
namespace flag {
inline constexpr std::uint16_t spindle_on = 1;
inline constexpr std::uint16_t inch = 2;             ///< program units are inches
inline constexpr std::uint16_t incremental = 4;      ///< G91 in effect
inline constexpr std::uint16_t program_end = 8;      ///< M02 / M30 executed
inline constexpr std::uint16_t owner_attached = 16;  ///< the transfer's owner has a live connection
}  // namespace flag

/// Standard Modbus exception codes used by the controller.
namespace exception_code {
inline constexpr int illegal_function = 1, illegal_address = 2, illegal_value = 3, device_failure = 4, device_busy = 6;
}
/// The Modbus exception code that goes with a refusal.
int exception_for(Reject r);

const char* to_string(State s);
const char* to_string(Alarm a);
const char* to_string(Reject r);
/// A sentence for people: what the refusal means and what to do.
std::string describe(Reject r);

/// The status block, decoded.
struct Status {
  std::uint16_t magic = 0, version = 0, buffer_capacity = 0, max_chunk = 0;
  std::uint32_t session = 0;
  State state = State::idle;
  Alarm alarm = Alarm::none;
  std::uint32_t alarm_line = 0, ack_seq = 0, ack_bytes = 0;
  std::uint16_t buffer_free = 0;
  Reject last_reject = Reject::none;
  std::uint32_t lines_executed = 0, blocks_executed = 0, program_crc = 0;
  std::int32_t pos[3] = {0, 0, 0};
  std::uint32_t feed_tenths = 0, spindle_rpm = 0;
  std::uint16_t flags = 0, tool = 0, motion = 0xFFFF, connections = 0;
  std::uint32_t duplicates = 0, rejects = 0, total_bytes = 0;
  /// Machine-pace execution (docs/motion.md): machine time (ms) the
  /// program stood still because the buffer ran dry before its end, and
  /// how many times that happened. 0 when executing as fast as possible.
  std::uint32_t starved_ms = 0, stalls = 0;

  /// Encodes into reg::status_count registers.
  std::array<std::uint16_t, reg::status_count> encode() const;
  /// Decodes reg::status_count registers (unknown enum values are kept as
  /// their numbers and print as "unknown").
  static Status decode(std::span<const std::uint16_t> regs);
};

/// 32-bit helpers (high word first).
inline void put_u32(std::uint16_t* r, std::uint32_t v) {
  r[0] = static_cast<std::uint16_t>(v >> 16);
  r[1] = static_cast<std::uint16_t>(v & 0xFFFFu);
}
inline std::uint32_t get_u32(const std::uint16_t* r) { return (std::uint32_t{r[0]} << 16) | r[1]; }

/// Packs bytes two per register, first byte high; `n_regs` registers are
/// written (zero padded). Bytes beyond 2 * n_regs are dropped.
void pack_text(std::string_view bytes, std::uint16_t* regs, std::size_t n_regs);
/// Unpacks `n_bytes` bytes; with `stop_at_nul` the text ends at the first NUL.
std::string unpack_text(std::span<const std::uint16_t> regs, std::size_t n_bytes, bool stop_at_nul);

/// One chunk as written to reg::chunk.
struct Chunk {
  std::uint32_t session = 0, seq = 0;
  std::string_view payload;  ///< 1..kMaxChunkBytes bytes
};
/// The registers of a chunk write: header then payload (7 + ceil(n/2)).
std::vector<std::uint16_t> encode_chunk(const Chunk& c);

/// The registers of a command write (code then arguments).
std::vector<std::uint16_t> encode_command(Command c, std::span<const std::uint32_t> args);

}  // namespace bezcam::link
