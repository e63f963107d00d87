#include "bezcam/link/register_map.hpp"

#include "bezcam/link/crc32.hpp"

// Tables of the register map (docs/modbus-register-map.md, sections 3 and
// 4). Codes are part of the protocol: never renumber, only append.
namespace bezcam::link {

std::uint16_t command_length(Command c) {
  switch (c) {
    case Command::open: return 5;
    case Command::resume: return 5;
    case Command::commit: return 9;
    case Command::abort: return 5;
    case Command::reset: return 1;
  }
  return 0;
}

// Standard exception codes only, so a generic master shows something
// meaningful: 02 for where, 03 for what, 04 for the controller's state, 06
// for "not now".
int exception_for(Reject r) {
  using namespace exception_code;
  switch (r) {
    case Reject::none: return 0;
    case Reject::bad_function: return illegal_function;
    case Reject::bad_address:
    case Reject::read_only: return illegal_address;
    case Reject::busy:
    case Reject::not_owner:
    case Reject::buffer_full: return device_busy;
    case Reject::not_receiving:
    case Reject::in_alarm: return device_failure;
    default: return illegal_value;
  }
}

const char* to_string(State s) {
  switch (s) {
    case State::idle: return "idle";
    case State::receiving: return "receiving";
    case State::finishing: return "finishing";
    case State::done: return "done";
    case State::alarm: return "alarm";
  }
  return "unknown";
}

const char* to_string(Alarm a) {
  switch (a) {
    case Alarm::none: return "none";
    case Alarm::gcode: return "gcode";
    case Alarm::travel_limit: return "travel-limit";
    case Alarm::feed_limit: return "feed-limit";
    case Alarm::line_too_long: return "line-too-long";
    case Alarm::crc_mismatch: return "crc-mismatch";
    case Alarm::length_mismatch: return "length-mismatch";
    case Alarm::incomplete: return "incomplete";
    case Alarm::sender_lost: return "sender-lost";
    case Alarm::aborted: return "aborted";
  }
  return "unknown";
}

const char* to_string(Reject r) {
  switch (r) {
    case Reject::none: return "none";
    case Reject::bad_function: return "bad-function";
    case Reject::bad_address: return "bad-address";
    case Reject::read_only: return "read-only";
    case Reject::bad_count: return "bad-count";
    case Reject::bad_command: return "bad-command";
    case Reject::busy: return "busy";
    case Reject::not_owner: return "not-owner";
    case Reject::bad_token: return "bad-token";
    case Reject::bad_session: return "bad-session";
    case Reject::not_receiving: return "not-receiving";
    case Reject::in_alarm: return "in-alarm";
    case Reject::seq_gap: return "seq-gap";
    case Reject::bad_length: return "bad-length";
    case Reject::bad_chunk_crc: return "bad-chunk-crc";
    case Reject::nul_byte: return "nul-byte";
    case Reject::buffer_full: return "buffer-full";
    case Reject::dup_mismatch: return "dup-mismatch";
  }
  return "unknown";
}

std::string describe(Reject r) {
  switch (r) {
    case Reject::none: return "no refusal";
    case Reject::bad_function: return "function code not supported (use 03, 04, 06, 16 or 23)";
    case Reject::bad_address: return "address outside the register map or not allowed for this function";
    case Reject::read_only: return "the status and text registers are read-only";
    case Reject::bad_count: return "register count out of range for the function";
    case Reject::bad_command: return "unknown command or wrong number of command registers";
    case Reject::busy: return "another sender owns the open transfer; wait until it is done or aborted";
    case Reject::not_owner: return "this connection does not own the transfer (send OPEN or RESUME first)";
    case Reject::bad_token: return "the token does not match the transfer's owner";
    case Reject::bad_session: return "the session id does not match the open transfer";
    case Reject::not_receiving: return "no transfer is open (send OPEN first)";
    case Reject::in_alarm: return "the controller is in alarm";
    case Reject::seq_gap: return "sequence gap: a chunk is missing before this one";
    case Reject::bad_length: return "chunk length is 0, above the maximum, or does not match the registers written";
    case Reject::bad_chunk_crc: return "chunk CRC-32 does not match its payload";
    case Reject::nul_byte: return "chunk payload holds a NUL byte";
    case Reject::buffer_full: return "the chunk does not fit in the receive buffer now; retry when buffer_free allows";
    case Reject::dup_mismatch: return "a retransmitted chunk differs from the chunk applied under that sequence number";
  }
  return "unknown refusal code";
}

// Every field in its documented register, 32-bit values high word first.
std::array<std::uint16_t, reg::status_count> Status::encode() const {
  std::array<std::uint16_t, reg::status_count> r{};
  r[reg::magic] = magic;
  r[reg::version] = version;
  r[reg::buffer_capacity] = buffer_capacity;
  r[reg::max_chunk] = max_chunk;
  put_u32(&r[reg::session], session);
  r[reg::state] = static_cast<std::uint16_t>(state);
  r[reg::alarm] = static_cast<std::uint16_t>(alarm);
  put_u32(&r[reg::alarm_line], alarm_line);
  put_u32(&r[reg::ack_seq], ack_seq);
  put_u32(&r[reg::ack_bytes], ack_bytes);
  r[reg::buffer_free] = buffer_free;
  r[reg::last_reject] = static_cast<std::uint16_t>(last_reject);
  put_u32(&r[reg::lines_executed], lines_executed);
  put_u32(&r[reg::blocks_executed], blocks_executed);
  put_u32(&r[reg::program_crc], program_crc);
  for (int a = 0; a < 3; ++a) put_u32(&r[reg::pos_x + 2 * a], static_cast<std::uint32_t>(pos[a]));
  put_u32(&r[reg::feed], feed_tenths);
  put_u32(&r[reg::spindle_rpm], spindle_rpm);
  r[reg::flags] = flags;
  r[reg::tool] = tool;
  r[reg::motion] = motion;
  r[reg::connections] = connections;
  put_u32(&r[reg::duplicates], duplicates);
  put_u32(&r[reg::rejects], rejects);
  put_u32(&r[reg::total_bytes], total_bytes);
  put_u32(&r[reg::starved_ms], starved_ms);
  put_u32(&r[reg::stalls], stalls);
  return r;
}

Status Status::decode(std::span<const std::uint16_t> r) {
  Status s;
  if (r.size() < reg::status_count) return s;
  s.magic = r[reg::magic];
  s.version = r[reg::version];
  s.buffer_capacity = r[reg::buffer_capacity];
  s.max_chunk = r[reg::max_chunk];
  s.session = get_u32(&r[reg::session]);
  s.state = static_cast<State>(r[reg::state]);
  s.alarm = static_cast<Alarm>(r[reg::alarm]);
  s.alarm_line = get_u32(&r[reg::alarm_line]);
  s.ack_seq = get_u32(&r[reg::ack_seq]);
  s.ack_bytes = get_u32(&r[reg::ack_bytes]);
  s.buffer_free = r[reg::buffer_free];
  s.last_reject = static_cast<Reject>(r[reg::last_reject]);
  s.lines_executed = get_u32(&r[reg::lines_executed]);
  s.blocks_executed = get_u32(&r[reg::blocks_executed]);
  s.program_crc = get_u32(&r[reg::program_crc]);
  for (int a = 0; a < 3; ++a) s.pos[a] = static_cast<std::int32_t>(get_u32(&r[reg::pos_x + 2 * a]));
  s.feed_tenths = get_u32(&r[reg::feed]);
  s.spindle_rpm = get_u32(&r[reg::spindle_rpm]);
  s.flags = r[reg::flags];
  s.tool = r[reg::tool];
  s.motion = r[reg::motion];
  s.connections = r[reg::connections];
  s.duplicates = get_u32(&r[reg::duplicates]);
  s.rejects = get_u32(&r[reg::rejects]);
  s.total_bytes = get_u32(&r[reg::total_bytes]);
  s.starved_ms = get_u32(&r[reg::starved_ms]);
  s.stalls = get_u32(&r[reg::stalls]);
  return s;
}

void pack_text(std::string_view bytes, std::uint16_t* regs, std::size_t n_regs) {
  for (std::size_t i = 0; i < n_regs; ++i) {
    const std::size_t b = 2 * i;
    const unsigned hi = b < bytes.size() ? static_cast<unsigned char>(bytes[b]) : 0u;
    const unsigned lo = b + 1 < bytes.size() ? static_cast<unsigned char>(bytes[b + 1]) : 0u;
    regs[i] = static_cast<std::uint16_t>((hi << 8) | lo);
  }
}

std::string unpack_text(std::span<const std::uint16_t> regs, std::size_t n_bytes, bool stop_at_nul) {
  std::string s;
  s.reserve(n_bytes);
  for (std::size_t b = 0; b < n_bytes && b / 2 < regs.size(); ++b) {
    const std::uint16_t r = regs[b / 2];
    const char c = static_cast<char>(b % 2 == 0 ? (r >> 8) : (r & 0xFF));
    if (stop_at_nul && c == '\0') break;
    s.push_back(c);
  }
  return s;
}

// Header (session, seq, length, CRC-32 of the payload), then the payload
// packed like any text; the CRC lets the controller refuse a chunk damaged
// anywhere between the sender's memory and its own.
std::vector<std::uint16_t> encode_chunk(const Chunk& c) {
  const std::size_t n = c.payload.size();
  std::vector<std::uint16_t> r(reg::chunk_header + (n + 1) / 2);
  put_u32(&r[0], c.session);
  put_u32(&r[2], c.seq);
  r[4] = static_cast<std::uint16_t>(n);
  put_u32(&r[5], crc32(c.payload));
  pack_text(c.payload, r.data() + reg::chunk_header, r.size() - reg::chunk_header);
  return r;
}

std::vector<std::uint16_t> encode_command(Command c, std::span<const std::uint32_t> args) {
  std::vector<std::uint16_t> r(1 + 2 * args.size());
  r[0] = static_cast<std::uint16_t>(c);
  for (std::size_t i = 0; i < args.size(); ++i) put_u32(&r[1 + 2 * i], args[i]);
  return r;
}

}  // namespace bezcam::link
