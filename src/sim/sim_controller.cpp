#include "bezcam/sim/sim_controller.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "bezcam/error.hpp"
#include "bezcam/sim/trace.hpp"

// The controller's side of docs/modbus-register-map.md. One mutex guards
// the transfer and the status; requests hold it only while they decide and
// read, and the executor releases it while a line runs and its trace is
// written, so a slow line or a slow disk never delays a reply.
namespace bezcam::sim {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kRecentChunks = 64;                      // retransmissions are checked against this many
constexpr ConnId kLocal = std::numeric_limits<ConnId>::max();  // run_program's "connection"

// The interpreter's error ids say what kind of refusal it was; the alarm
// code is the coarse, numbered version a PLC can switch on.
// The alarm code is a function of the error id alone.
Alarm alarm_for(const std::string& id) {
  if (id == errc::gcode_travel) return Alarm::travel_limit;
  if (id == errc::gcode_feed_limit) return Alarm::feed_limit;
  if (id == errc::gcode_nurbs_open) return Alarm::incomplete;
  return Alarm::gcode;
}

std::int32_t thousandths(double v) {
  const double t = std::round(v * 1000.0);
  if (!(t == t)) return 0;
  return static_cast<std::int32_t>(std::clamp(t, -2147483648.0, 2147483647.0));
}

}  // namespace

struct SimController::Pending {
  std::uint64_t epoch = 0;
  std::string text;  // the trace record
};

SimController::SimController(ControllerConfig cfg) : cfg_(std::move(cfg)) {
  if (cfg_.buffer_bytes < kMinBuffer || cfg_.buffer_bytes > kMaxBuffer)
    throw InputError(errc::sim_config, Place::at_register("buffer"),
                     "the receive buffer must hold " + std::to_string(kMinBuffer) + " to " +
                         std::to_string(kMaxBuffer) + " bytes, found " + std::to_string(cfg_.buffer_bytes));
  if (cfg_.session_timeout.count() <= 0)
    throw InputError(errc::sim_config, Place::at_register("session timeout"),
                     "must be positive, found " + std::to_string(cfg_.session_timeout.count()) + " ms");
  if (cfg_.stock)
    stock_ = std::make_unique<StockCutter>(cfg_.stock->box, cfg_.stock->cell, cfg_.stock->tools, cfg_.stock->options);
  buf_.reserve(cfg_.buffer_bytes);
  exec_ = std::thread([this] { exec_loop(); });
}

SimController::~SimController() { stop(); }

void SimController::stop() {
  {
    std::lock_guard lk(m_);
    stop_ = true;
  }
  cv_.notify_all();
  if (exec_.joinable()) exec_.join();
}

ConnId SimController::connection_opened() {
  std::lock_guard lk(m_);
  const ConnId id = next_conn_++;
  ++connections_;
  last_reject_[id] = Reject::none;
  log_locked("connection " + std::to_string(id) + " opened (" + std::to_string(connections_) + " open)");
  return id;
}

void SimController::connection_closed(ConnId c) {
  std::lock_guard lk(m_);
  if (connections_ > 0) --connections_;
  last_reject_.erase(c);
  log_locked("connection " + std::to_string(c) + " closed" +
             (owner_ == c && (state_ == State::receiving || state_ == State::finishing)
                  ? " while it owned the transfer (it may resume)"
                  : std::string()));
  // The transfer survives its owner's connection: the sender may come back
  // and RESUME until the session timeout runs out.
  if (owner_ == c) owner_ = 0;
}

ConnId SimController::owner() const {
  std::lock_guard lk(m_);
  return owner_;
}

std::uint32_t SimController::next_session_locked() {
  std::uint32_t s = 0;
  if (cfg_.first_session != 0) {
    s = last_session_ == 0 ? cfg_.first_session : last_session_ + 1;
    if (s == 0) s = 1;
  } else {
    // A restarted controller must not hand out the id of the transfer it
    // lost, or a sender could resume into a different program: 32 random
    // bits make that a one-in-four-billion event.
    std::random_device rd;
    do s = static_cast<std::uint32_t>(rd());
    while (s == 0 || s == last_session_);
  }
  last_session_ = s;
  return s;
}

// A new program starts from nothing: buffer, counters, alarm and machine
// state are reset here; the executor sees the new epoch and restarts the
// interpreter and the trace itself (they belong to its thread).
void SimController::open_locked(ConnId c, std::uint32_t token, std::uint32_t total) {
  ++epoch_;
  session_ = next_session_locked();
  token_ = token;
  total_ = total;
  owner_ = c;
  owner_seen_ = Clock::now();
  state_ = State::receiving;
  ack_seq_ = ack_bytes_ = 0;
  crc_ = Crc32{};
  committed_ = false;
  commit_total_ = commit_crc_ = 0;
  buf_.clear();
  head_ = 0;
  recent_.clear();
  duplicates_ = 0;
  alarm_ = Alarm::none;
  alarm_line_ = 0;
  alarm_message_.clear();
  alarm_id_.clear();
  final_traced_ = false;
  line_no_ = lines_done_ = blocks_done_ = 0;
  machine_ = MachineState{};
  reset_paced_locked();
  cv_.notify_all();
  char sid[16];
  std::snprintf(sid, sizeof sid, "%08x", session_);
  log_locked(c == kLocal ? "program opened: " + std::to_string(total) + " bytes"
                         : "program opened by connection " + std::to_string(c) + ": session " + sid + ", " +
                               std::to_string(total) + " bytes");
}

void SimController::log_locked(const std::string& event) const {
  if (cfg_.on_event) cfg_.on_event(event);
}

// For alarms raised by requests (COMMIT checks, ABORT) and by the lease: the
// state changes at once, so further chunks are refused, and the executor
// writes the record into the trace (only it writes the trace).
void SimController::raise_alarm_locked(Alarm a, long line, std::string id, std::string message) {
  if (state_ == State::alarm) return;  // the first alarm is the one that counts
  // At machine pace the machine stops where it is: the lines it finished go
  // into the trace before the alarm, the ones read ahead never run.
  std::string done;
  if (paced_locked()) {
    const MachineView v = freeze_locked(done);
    if (line == kMachineLine) line = v.reached;
  } else if (line == kMachineLine) {
    line = line_no_;
  }
  // A controller in alarm stops the spindle and the coolant.
  machine_.spindle_on = false;
  machine_.coolant_mist = machine_.coolant_flood = false;
  record_alarm_locked(a, line, id, message);
  final_traced_ = false;
  pending_alarm_ =
      std::make_unique<Pending>(Pending{epoch_, done + trace_alarm(static_cast<int>(line), to_string(a), id, message)});
  cv_.notify_all();
}

Status SimController::status_locked(ConnId c) const {
  // At machine pace, what the machine has done by now.
  MachineState m = machine_;
  long lines = lines_done_, blocks = blocks_done_;
  if (paced_locked()) {
    const MachineView v = view_locked(pace_now());
    m = v.state;
    lines = v.lines;
    blocks = v.blocks;
  }
  Status s;
  s.magic = kMagic;
  s.version = kProtocolVersion;
  s.buffer_capacity = static_cast<std::uint16_t>(cfg_.buffer_bytes);
  s.max_chunk = kMaxChunkBytes;
  s.session = session_;
  s.state = state_;
  s.alarm = alarm_;
  s.alarm_line = alarm_line_;
  s.ack_seq = ack_seq_;
  s.ack_bytes = ack_bytes_;
  s.buffer_free = static_cast<std::uint16_t>(cfg_.buffer_bytes - buffered_locked());
  if (const auto it = last_reject_.find(c); it != last_reject_.end()) s.last_reject = it->second;
  s.lines_executed = static_cast<std::uint32_t>(lines);
  s.blocks_executed = static_cast<std::uint32_t>(blocks);
  s.program_crc = crc_.value();
  for (int a = 0; a < 3; ++a) s.pos[a] = thousandths(m.pos[a]);
  s.feed_tenths = static_cast<std::uint32_t>(std::clamp(std::round(m.feed * 10.0), 0.0, 4294967295.0));
  s.spindle_rpm = static_cast<std::uint32_t>(std::clamp(std::round(m.spindle_rpm), 0.0, 4294967295.0));
  s.flags =
      static_cast<std::uint16_t>((m.spindle_on ? flag::spindle_on : 0) | (m.units == Units::inch ? flag::inch : 0) |
                                 (m.distance == DistanceMode::absolute ? 0 : flag::incremental) |
                                 (m.program_end ? flag::program_end : 0) | (owner_ != 0 ? flag::owner_attached : 0));
  s.tool = static_cast<std::uint16_t>(std::clamp(m.tool, 0, 65535));
  // Register 34 (docs/modbus-register-map.md): 0-3 for G00-G03, the G
  // number x 10 for curve modes (G5.2 -> 52), 0xFFFF none.
  const int code10 = static_cast<int>(m.motion);
  s.motion = m.motion == ModalMotion::none ? std::uint16_t{0xFFFF}
                                           : static_cast<std::uint16_t>(code10 <= 30 ? code10 / 10 : code10);
  s.connections = static_cast<std::uint16_t>(std::min<std::size_t>(connections_, 65535));
  s.duplicates = duplicates_;
  s.rejects = rejects_;
  s.total_bytes = total_;
  s.starved_ms = starved_ms_;
  s.stalls = stalls_;
  return s;
}

Status SimController::status(ConnId c) const {
  std::lock_guard lk(m_);
  return status_locked(c);
}

std::string SimController::alarm_text() const {
  std::lock_guard lk(m_);
  return alarm_text_locked();
}

std::string SimController::alarm_message() const {
  std::lock_guard lk(m_);
  return alarm_message_;
}

std::string SimController::alarm_id() const {
  std::lock_guard lk(m_);
  return alarm_id_;
}

std::string SimController::alarm_text_locked() const {
  return (alarm_line_ > 0 ? "line " + std::to_string(alarm_line_) + ": " : std::string()) + alarm_message_;
}

// The line travels as a number (register alarm_line); only the text for
// people (register alarm_text, the operator's log) spells it out.
void SimController::record_alarm_locked(Alarm a, long line, std::string id, std::string message) {
  state_ = State::alarm;
  alarm_ = a;
  alarm_id_ = std::move(id);
  alarm_line_ = static_cast<std::uint32_t>(std::max(0L, line));
  alarm_message_ = std::move(message);
  log_locked(std::string("alarm ") + to_string(a) + ": " + alarm_text_locked());
}

// The readable registers are rebuilt per read from the live state, so a
// read never sees half an update.
std::vector<std::uint16_t> SimController::read_locked(ConnId c, std::uint16_t addr, std::uint16_t n) const {
  std::array<std::uint16_t, reg::readable_end> image{};
  const auto st = status_locked(c).encode();
  std::copy(st.begin(), st.end(), image.begin());
  pack_text(alarm_text_locked(), &image[reg::alarm_text], reg::alarm_text_count);
  pack_text(cfg_.profile.name, &image[reg::machine_name], reg::machine_name_count);
  return {image.begin() + addr, image.begin() + addr + n};
}

// Checks in the order that gives the most useful refusal: state, ownership,
// session, then the sequence rules of section 5, then room in the buffer.
Reject SimController::apply_chunk_locked(ConnId c, std::uint32_t session, std::uint32_t seq, std::string_view payload,
                                         std::uint32_t crc) {
  if (state_ == State::alarm) return Reject::in_alarm;
  if (state_ != State::receiving) return Reject::not_receiving;
  if (c != owner_) return Reject::not_owner;
  if (session != session_) return Reject::bad_session;
  const auto len = static_cast<std::uint16_t>(payload.size());
  if (seq <= ack_seq_) {
    // A retransmission (its acknowledgement was lost): acknowledge it again
    // without applying it, after checking it is the chunk that was applied.
    for (const auto& r : recent_)
      if (r.seq == seq && (r.len != len || r.crc != crc)) return Reject::dup_mismatch;
    ++duplicates_;
    return Reject::none;
  }
  if (seq != ack_seq_ + 1) return Reject::seq_gap;
  if (payload.size() > cfg_.buffer_bytes - buffered_locked()) return Reject::buffer_full;
  if (std::uint64_t{ack_bytes_} + payload.size() > std::numeric_limits<std::uint32_t>::max()) return Reject::bad_length;
  if (head_ > 0 && head_ * 2 >= buf_.size()) {  // compact: amortised O(1) per byte
    buf_.erase(0, head_);
    head_ = 0;
  }
  buf_.append(payload);
  crc_.update(payload);
  ack_seq_ = seq;
  ack_bytes_ += len;
  if (recent_.size() == kRecentChunks) recent_.erase(recent_.begin());
  recent_.push_back({seq, crc, len});
  cv_.notify_all();
  return Reject::none;
}

// Decodes and checks the chunk's own integrity (length against the
// registers written, CRC-32, no NUL) before any state is looked at.
Reject SimController::chunk_locked(ConnId c, std::span<const std::uint16_t> regs, bool corrupt) {
  if (regs.size() <= reg::chunk_header) return Reject::bad_length;
  const std::uint32_t session = get_u32(&regs[0]), seq = get_u32(&regs[2]), crc = get_u32(&regs[5]);
  const std::uint16_t len = regs[4];
  if (len == 0 || len > kMaxChunkBytes || regs.size() != reg::chunk_header + (len + 1u) / 2u) return Reject::bad_length;
  std::string payload = unpack_text(regs.subspan(reg::chunk_header), len, false);
  if (crc32(payload) != crc) return Reject::bad_chunk_crc;
  if (payload.find('\0') != std::string::npos) return Reject::nul_byte;
  if (corrupt && seq == ack_seq_ + 1)
    if (const auto d = payload.find_first_of("0123456789"); d != std::string::npos)
      payload[d] = payload[d] == '0' ? '1' : static_cast<char>(payload[d] - 1);
  return apply_chunk_locked(c, session, seq, payload, crc);
}

// Commands are whole writes at 0x0100 with an exact register count, so a
// truncated or misaddressed command can never be half-understood.
Reject SimController::command_locked(ConnId c, std::span<const std::uint16_t> regs) {
  if (regs.empty()) return Reject::bad_command;
  const auto code = static_cast<Command>(regs[0]);
  if (regs[0] < 1 || regs[0] > 5 || regs.size() != command_length(code)) return Reject::bad_command;
  auto arg = [&](int i) { return get_u32(&regs[static_cast<std::size_t>(1 + 2 * i)]); };
  const bool active = state_ == State::receiving || state_ == State::finishing;
  switch (code) {
    case Command::open: {
      const std::uint32_t token = arg(0), total = arg(1);
      if (token == 0) return Reject::bad_command;
      if (active) {
        // The same sender repeating an OPEN whose reply it lost gets the
        // same transfer back; anyone else waits.
        if (token == token_ && state_ == State::receiving && ack_bytes_ == 0) {
          owner_ = c;
          owner_seen_ = Clock::now();
          return Reject::none;
        }
        return Reject::busy;
      }
      open_locked(c, token, total);
      return Reject::none;
    }
    case Command::resume: {
      if (session_ == 0 || arg(1) != session_) return Reject::bad_session;
      if (arg(0) != token_) return Reject::bad_token;
      owner_ = c;
      owner_seen_ = Clock::now();
      return Reject::none;
    }
    case Command::commit: {
      if (session_ == 0 || arg(1) != session_) return Reject::bad_session;
      if (arg(0) != token_) return Reject::bad_token;
      const std::uint32_t total = arg(2), crc = arg(3);
      if (state_ == State::finishing || state_ == State::done)  // repeated COMMIT: same answer
        return committed_ && total == commit_total_ && crc == commit_crc_ ? Reject::none : Reject::not_receiving;
      if (state_ == State::alarm) return Reject::in_alarm;
      if (state_ != State::receiving) return Reject::not_receiving;
      owner_ = c;
      owner_seen_ = Clock::now();
      if (total != ack_bytes_) {
        raise_alarm_locked(Alarm::length_mismatch, 0, errc::link_length_mismatch,
                           "the sender's program has " + std::to_string(total) + " bytes, the controller received " +
                               std::to_string(ack_bytes_));
        return Reject::in_alarm;
      }
      if (crc != crc_.value()) {
        raise_alarm_locked(
            Alarm::crc_mismatch, 0, errc::link_crc_mismatch,
            "CRC-32 of the received program is " + hex32(crc_.value()) + ", the sender's is " + hex32(crc));
        return Reject::in_alarm;
      }
      committed_ = true;
      commit_total_ = total;
      commit_crc_ = crc;
      state_ = State::finishing;
      cv_.notify_all();
      return Reject::none;
    }
    case Command::abort: {
      if (session_ == 0 || arg(1) != session_) return Reject::bad_session;
      // Token 0 is the operator's stop (bezcam stream --abort): anyone may
      // stop the open transfer; only its sender may start or feed one.
      const bool operator_stop = arg(0) == 0;
      if (!operator_stop && arg(0) != token_) return Reject::bad_token;
      if (active)
        raise_alarm_locked(
            Alarm::aborted, kMachineLine, errc::link_aborted,
            (operator_stop ? "the operator stopped the transfer after " : "the sender aborted the transfer after ") +
                std::to_string(ack_bytes_) + " bytes");
      return Reject::none;
    }
    case Command::reset: {
      if (active) return Reject::busy;
      state_ = State::idle;
      alarm_ = Alarm::none;
      alarm_line_ = 0;
      alarm_message_.clear();
      session_ = token_ = total_ = 0;
      owner_ = 0;
      ack_seq_ = ack_bytes_ = 0;
      crc_ = Crc32{};
      buf_.clear();
      head_ = 0;
      return Reject::none;
    }
  }
  return Reject::bad_command;
}

FrameReply SimController::handle_frame(ConnId c, std::span<const std::uint8_t> adu) {
  FrameReply out;
  auto u16 = [&](std::size_t i) { return static_cast<std::uint16_t>((adu[i] << 8) | adu[i + 1]); };
  // MBAP header: transaction id, protocol id (0), length of what follows
  // (unit id + PDU), unit id. A frame that contradicts itself cannot be
  // answered safely: drop the connection.
  if (adu.size() < 8 || adu.size() > 260 || u16(2) != 0 || u16(4) != adu.size() - 6) {
    out.drop = true;
    return out;
  }
  const std::uint8_t fc = adu[7];
  const std::size_t pdu = adu.size() - 7;  // function code + data
  std::lock_guard lk(m_);
  // Any request from the owner, reads included, renews its lease.
  if (c == owner_ && c != 0) owner_seen_ = Clock::now();
  auto refuse = [&](Reject why) {
    ++rejects_;
    last_reject_[c] = why;
    out.exception = exception_for(why);
    out.regs.clear();
    return out;
  };
  auto regs_at = [&](std::size_t off, std::size_t n) {
    std::vector<std::uint16_t> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = u16(off + 2 * i);
    return v;
  };
  // Routes a write: status and text are read-only, the command block and
  // the chunk window take whole writes from their first register.
  auto write = [&](std::uint16_t addr, const std::vector<std::uint16_t>& v) -> Reject {
    if (addr < reg::readable_end) return Reject::read_only;
    if (addr == reg::command) return command_locked(c, v);
    if (addr != reg::chunk) return Reject::bad_address;
    const std::uint64_t n = ++chunk_requests_;
    auto fires = [&](std::vector<std::uint64_t>& list) {
      const auto it = std::find(list.begin(), list.end(), n);
      if (it == list.end()) return false;
      list.erase(it);
      return true;
    };
    if (fires(cfg_.drop_before_chunk)) {
      out.drop = true;
      return Reject::none;
    }
    const Reject r = chunk_locked(c, v, fires(cfg_.corrupt_chunk));
    if (fires(cfg_.drop_after_chunk)) out.drop = true;
    return r;
  };
  switch (fc) {
    case 3:
    case 4: {
      // FC 03 / 04: address, count. Both tables hold the same registers.
      if (pdu != 5) return refuse(Reject::bad_count);
      const std::uint16_t addr = u16(8), n = u16(10);
      if (n < 1 || n > 125) return refuse(Reject::bad_count);
      if (addr + n > reg::readable_end) return refuse(Reject::bad_address);
      out.read_addr = addr;
      out.read_input = fc == 4;
      out.regs = read_locked(c, addr, n);
      return out;
    }
    case 6: {
      // FC 06: address, value. Only RESET is a one-register command.
      if (pdu != 5) return refuse(Reject::bad_count);
      const std::uint16_t addr = u16(8);
      if (addr != reg::command) return refuse(addr < reg::readable_end ? Reject::read_only : Reject::bad_address);
      if (const Reject r = command_locked(c, regs_at(10, 1)); r != Reject::none) return refuse(r);
      last_reject_[c] = Reject::none;
      return out;
    }
    case 16: {
      // FC 16: address, count, byte count, values.
      if (pdu < 6) return refuse(Reject::bad_count);
      const std::uint16_t addr = u16(8), n = u16(10);
      if (n < 1 || n > 123 || adu[12] != 2 * n || pdu != 6u + 2u * n) return refuse(Reject::bad_count);
      const Reject r = write(addr, regs_at(13, n));
      if (out.drop) return out;
      if (r != Reject::none) return refuse(r);
      last_reject_[c] = Reject::none;
      return out;
    }
    case 23: {
      // FC 23: read address, read count, write address, write count, byte
      // count, values. The write happens first, the read sees its effect.
      if (pdu < 10) return refuse(Reject::bad_count);
      const std::uint16_t raddr = u16(8), rn = u16(10), waddr = u16(12), wn = u16(14);
      if (rn < 1 || rn > 125 || wn < 1 || wn > 121 || adu[16] != 2 * wn || pdu != 10u + 2u * wn)
        return refuse(Reject::bad_count);
      // The read range is checked first so that a refused request changes nothing.
      if (raddr + rn > reg::readable_end) return refuse(Reject::bad_address);
      const Reject r = write(waddr, regs_at(17, wn));
      if (out.drop) return out;
      if (r != Reject::none) return refuse(r);
      last_reject_[c] = Reject::none;
      out.read_addr = raddr;
      out.regs = read_locked(c, raddr, rn);
      return out;
    }
    default: return refuse(Reject::bad_function);
  }
}

// `simulate --program`: the file goes through open/apply/commit exactly as
// a streamed one, as a local "connection", so both give the same trace.
Status SimController::run_program(std::string_view program) {
  if (const auto nul = program.find('\0'); nul != std::string_view::npos) {
    const auto line = 1 + std::count(program.begin(), program.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    throw InputError(errc::sim_nul_byte, Place::at_line(line),
                     "the program holds a NUL byte (offset " + std::to_string(nul) + "); G-code is text");
  }
  if (program.size() > std::numeric_limits<std::uint32_t>::max())
    throw InputError(errc::sim_too_large, Place{}, "the program is larger than 4 GiB, the protocol's limit");
  std::unique_lock lk(m_);
  if (state_ == State::receiving || state_ == State::finishing)
    throw InputError(errc::sim_busy, Place{}, "a streamed transfer is in progress; wait until it is done");
  constexpr std::uint32_t kToken = 0x4C4F434Cu;  // "LOCL"
  open_locked(kLocal, kToken, static_cast<std::uint32_t>(program.size()));
  std::uint32_t seq = 0;
  std::size_t off = 0;
  while (off < program.size()) {
    cv_.wait(lk, [&] { return stop_ || state_ != State::receiving || buffered_locked() < cfg_.buffer_bytes; });
    if (stop_ || state_ != State::receiving) break;
    owner_seen_ = Clock::now();
    const std::size_t n =
        std::min({std::size_t{kMaxChunkBytes}, cfg_.buffer_bytes - buffered_locked(), program.size() - off});
    const std::string_view piece = program.substr(off, n);
    if (apply_chunk_locked(kLocal, session_, ++seq, piece, crc32(piece)) != Reject::none) break;
    off += n;
  }
  if (!stop_ && state_ == State::receiving && off == program.size()) {
    const std::vector<std::uint16_t> commit = encode_command(
        Command::commit,
        std::array<std::uint32_t, 4>{kToken, session_, static_cast<std::uint32_t>(program.size()), crc32(program)});
    command_locked(kLocal, commit);
  }
  cv_.wait(lk, [&] {
    return stop_ || ((state_ == State::done || state_ == State::alarm) && final_traced_ && !pending_alarm_);
  });
  return status_locked(kLocal);
}

bool SimController::wait_final(std::chrono::milliseconds timeout) const {
  std::unique_lock lk(m_);
  return cv_.wait_for(lk, timeout, [&] {
    return (state_ == State::done || state_ == State::alarm) && final_traced_ && !pending_alarm_;
  });
}

// Called unlocked: a file sink may block on the disk.
void SimController::emit_trace(const std::string& text, bool restart) {
  if (cfg_.trace && !text.empty()) cfg_.trace(text, restart);
}

// Takes the line ending at `nl` (npos: the unterminated last line after
// COMMIT) out of the buffer, executes and traces it unlocked, and records
// the result unless the program was replaced meanwhile. `lk` is held on
// entry and on return.
void SimController::execute_line(std::unique_lock<std::mutex>& lk, GcodeInterpreter& interp, std::uint64_t cur_epoch,
                                 std::size_t nl) {
  const std::size_t end = nl == std::string::npos ? buf_.size() : nl;
  std::string line = buf_.substr(head_, end - head_);
  head_ = nl == std::string::npos ? buf_.size() : nl + 1;
  if (head_ == buf_.size()) buf_.clear(), head_ = 0;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const long no = ++line_no_;
  cv_.notify_all();  // space freed: run_program may push more
  lk.unlock();
  if (cfg_.on_line) cfg_.on_line(no, line);
  if (cfg_.exec_delay.count() > 0) std::this_thread::sleep_for(cfg_.exec_delay);
  const MachineState before = interp.state();
  std::string text;
  std::vector<MotionBlock> blocks;
  std::optional<std::pair<Alarm, std::string>> failed;
  std::string id;
  try {
    blocks = interp.feed_line(line, static_cast<int>(no));
    // The stock: at machine pace the moves are cut once the machine has
    // run them, so only their tools are checked now.
    if (pace_)
      check_stock_tools(blocks, interp.state());
    else
      cut_stock(blocks, interp.state());
    for (const auto& b : blocks) text += trace_block(b);
    text += trace_state(static_cast<int>(no), before, interp.state());
  } catch (const Error& e) {
    id = e.id();
    failed.emplace(alarm_for(e.id()), e.message());
  } catch (const std::exception& e) {
    id = errc::sim_internal;
    failed.emplace(Alarm::gcode, std::string("internal error: ") + e.what());
  }
  // A line refused for its tool after the interpreter read it is not
  // executed either: its blocks are dropped and the state stays as before.
  if (failed) blocks.clear();
  if (failed) text += trace_alarm(static_cast<int>(no), to_string(failed->first), id, failed->second);
  // pace_ is the executor's own: read here without the lock.
  if (pace_) {
    lk.lock();
    read_ahead_locked(interp, cur_epoch, no, before, blocks, failed, id, std::move(text));
    return;
  }
  if (failed) text += stock_record();
  const std::size_t nblocks = blocks.size();
  emit_trace(text, false);
  lk.lock();
  if (epoch_ != cur_epoch) return;  // the program was replaced meanwhile
  if (!failed) ++lines_done_;       // a refused line changed nothing: it was not executed
  blocks_done_ += static_cast<long>(nblocks);
  machine_ = failed ? before : interp.state();
  if (state_ == State::alarm || failed) machine_.spindle_on = machine_.coolant_mist = machine_.coolant_flood = false;
  if (failed && state_ != State::alarm) {
    // Traced above already, so no pending record.
    record_alarm_locked(failed->first, no, id, failed->second);
    final_traced_ = true;
  }
  cv_.notify_all();
}

// Every byte confirmed and executed: ends the program (interpreter's
// finish, DONE record) and sets DONE, or ALARM when it is incomplete.
// `lk` is held on entry and on return.
void SimController::finish_program(std::unique_lock<std::mutex>& lk, GcodeInterpreter& interp,
                                   std::uint64_t cur_epoch) {
  const long lines = line_no_;
  lk.unlock();
  std::string text;
  std::optional<std::pair<std::string, std::string>> failed;
  long nblocks = 0;
  try {
    const auto blocks = interp.finish();
    cut_stock(blocks, interp.state());
    nblocks = static_cast<long>(blocks.size());
    for (const auto& b : blocks) text += trace_block(b);
  } catch (const Error& e) {
    failed.emplace(e.id(), e.message());
  }
  // A move held until the end refused for its tool is the program's fault,
  // not a program cut short.
  const Alarm end_alarm = failed && failed->first == errc::verify_tool.str() ? Alarm::gcode : Alarm::incomplete;
  lk.lock();
  const long total_blocks = blocks_done_ + nblocks;
  const Vec3 pos = interp.state().pos;
  lk.unlock();
  text += failed ? trace_alarm(static_cast<int>(lines), to_string(end_alarm), failed->first, failed->second)
                 : trace_done(lines, total_blocks, pos);
  text += stock_record();
  emit_trace(text, false);
  lk.lock();
  if (epoch_ != cur_epoch || state_ != State::finishing) return;
  blocks_done_ = total_blocks;
  machine_ = interp.state();
  if (failed) {
    record_alarm_locked(end_alarm, lines, failed->first, failed->second);
  } else {
    state_ = State::done;  // only now: the trace on disk is complete
    log_locked("program done: " + std::to_string(lines) + " lines, " + std::to_string(total_blocks) + " motion blocks");
  }
  final_traced_ = true;
  cv_.notify_all();
}

void SimController::exec_loop() {
  std::unique_lock lk(m_);
  std::uint64_t cur_epoch = 0;
  std::unique_ptr<GcodeInterpreter> interp;
  while (!stop_) {
    // 1. An alarm raised by a request (COMMIT checks, ABORT, lease): trace
    // it for the program it stopped, starting that program's trace first
    // if the executor had not got to it yet.
    if (pending_alarm_) {
      const Pending p = *pending_alarm_;
      pending_alarm_.reset();
      const bool restart = p.epoch != cur_epoch;
      if (restart) cur_epoch = p.epoch, interp.reset();
      const std::vector<StockMove> moves = take_stock_locked();
      lk.unlock();
      const std::string text = p.text + stock_record(moves);
      emit_trace(restart ? trace_header(cfg_.profile.name) + text : text, restart);
      lk.lock();
      if (epoch_ == p.epoch) final_traced_ = true;
      cv_.notify_all();
      continue;
    }
    // 2. A new program: fresh interpreter (modal state from power-on) and a
    // fresh trace.
    if (epoch_ != cur_epoch) {
      cur_epoch = epoch_;
      interp = std::make_unique<GcodeInterpreter>(&cfg_.profile);
      pace_.reset();
      if (cfg_.time_scale > 0 && cfg_.profile.motion) pace_ = std::make_unique<MachinePace>(*cfg_.profile.motion);
      reset_paced_locked();
      starved_ms_ = stalls_ = 0;
      lk.unlock();
      emit_trace(trace_header(cfg_.profile.name), true);
      lk.lock();
      continue;
    }
    const bool running = state_ == State::receiving || state_ == State::finishing;
    std::optional<Clock::time_point> machine_wake;  // machine pace: when the machine needs work
    if (running && interp) {
      // 3. At machine pace, the lines the machine has finished go into the
      // trace.
      if (pace_ && retire_step(lk)) continue;
      // 3a. Drip feed: execute every complete line as soon as it is in the
      // buffer; after COMMIT the last line needs no newline. At machine
      // pace, only while the look-ahead window has room, and none after a
      // refused line.
      const auto nl = buf_.find('\n', head_);
      const bool line_ready = nl != std::string::npos || (state_ == State::finishing && buffered_locked() > 0);
      if (line_ready && !failure_ && (!pace_ || !pace_->window_full())) {
        if (pace_) machine_fed_locked();
        execute_line(lk, *interp, cur_epoch, nl);
        continue;
      }
      // 3b. At machine pace, the machine moves through what it was given.
      if (pace_ && machine_step(lk, cur_epoch, line_ready, machine_wake)) continue;
      // 4. End of program: every byte confirmed and executed (at machine
      // pace: read, then run by the machine, which is at rest at its end).
      if (state_ == State::finishing && !line_ready && !failure_) {
        if (!pace_) {
          finish_program(lk, *interp, cur_epoch);
          continue;
        }
        if (!interp_finished_) {
          finish_interpreter(lk, *interp, cur_epoch);
          continue;
        }
        if (!machine_wake && pace_->pending() == 0) {
          finish_paced(lk, *interp, cur_epoch);
          continue;
        }
      }
      // 5. A full buffer with no line end can never make progress (at
      // machine pace, once the machine has run what it has).
      if (!line_ready && !failure_ && buffered_locked() >= cfg_.buffer_bytes) {
        const std::string message =
            "the line is longer than the receive buffer (" + std::to_string(cfg_.buffer_bytes) + " bytes)";
        if (pace_) {
          failure_ = Failure{Alarm::line_too_long, line_no_ + 1, std::string(errc::sim_line_too_long.str()), message,
                             trace_alarm(static_cast<int>(line_no_ + 1), to_string(Alarm::line_too_long),
                                         errc::sim_line_too_long.str(), message)};
        } else {
          raise_alarm_locked(Alarm::line_too_long, line_no_ + 1, errc::sim_line_too_long, message);
        }
        continue;
      }
    }
    // 6. The owner's lease: a transfer nobody feeds is stopped, so that a
    // vanished sender does not hold the controller forever.
    if (state_ == State::receiving) {
      const auto deadline = owner_seen_ + cfg_.session_timeout;
      if (Clock::now() >= deadline) {
        raise_alarm_locked(Alarm::sender_lost, kMachineLine, errc::link_sender_lost,
                           "the sender was silent for " + std::to_string(cfg_.session_timeout.count()) +
                               " ms; the program is incomplete");
        continue;
      }
      cv_.wait_until(lk, machine_wake ? std::min(deadline, *machine_wake) : deadline);
    } else if (machine_wake) {
      cv_.wait_until(lk, *machine_wake);
    } else {
      cv_.wait(lk);
    }
  }
  // Stopped (SIGINT/SIGTERM): record what is still unsaid so the trace on
  // disk is complete up to here.
  std::string tail;
  if (pending_alarm_) {
    tail = pending_alarm_->epoch == cur_epoch ? pending_alarm_->text : std::string();
    pending_alarm_.reset();
    final_traced_ = true;
  } else if (interp && (state_ == State::receiving || state_ == State::finishing)) {
    long last = line_no_;
    if (pace_ && pace_started_) last = freeze_locked(tail).done_line;  // the machine stops where it is
    tail += "stopped after line " + std::to_string(last) + "\n";
  }
  const std::vector<StockMove> moves = take_stock_locked();
  lk.unlock();
  if (!tail.empty()) tail += stock_record(moves);
  emit_trace(tail, false);
  cv_.notify_all();
}

}  // namespace bezcam::sim
