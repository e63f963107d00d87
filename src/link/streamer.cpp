#include "bezcam/link/streamer.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <random>
#include <thread>
#include <vector>

#include "bezcam/link/crc32.hpp"

// The sender's side of docs/modbus-register-map.md, section 6. The design
// rule throughout: the controller's acknowledged position is the truth. The
// sender never resends from its own count, never assumes a request that got
// no reply was or was not applied, and never reports success before the
// controller itself has confirmed length and CRC-32 and reached DONE.
namespace bezcam::link {

namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// One transfer, from OPEN to DONE; not reusable.
class Sender {
 public:
  Sender(std::string_view program, const TransportFactory& connect, const std::string& peer, const StreamOptions& opt)
      : prog_(program), connect_(connect), peer_(peer), opt_(opt), crc_(crc32(program)) {
    // Line ends, to turn acknowledged bytes into lines for progress.
    for (std::size_t i = 0; i < prog_.size(); ++i)
      if (prog_[i] == '\n') newlines_.push_back(i);
    lines_total_ = newlines_.size() + (prog_.empty() || prog_.back() == '\n' ? 0 : 1);
    // The token proves, after a reconnection, that this sender opened the
    // transfer; the session id alone is readable by anyone.
    std::random_device rd;
    do token_ = static_cast<std::uint32_t>(rd());
    while (token_ == 0);
  }

  StreamResult run() {
    start_ = Clock::now();
    client_ = connect_(opt_.timeout);
    st_ = read_status();
    check_identity();
    check_cancel();
    open();
    send_all();
    commit();
    wait_done();
    StreamResult r;
    r.session = session_;
    r.crc = crc_;
    r.bytes = prog_.size();
    r.lines = lines_total_;
    r.chunks = chunks_;
    r.lines_executed = st_.lines_executed;
    r.blocks_executed = st_.blocks_executed;
    r.starved_ms = st_.starved_ms;
    r.stalls = st_.stalls;
    r.reconnects = reconnects_;
    r.seconds = seconds();
    return r;
  }

 private:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  Status read_status() {
    std::array<std::uint16_t, reg::status_count> r{};
    client_->read_holding(0, r);
    return Status::decode(r);
  }

  // FC 23: the write and the status after it in one round trip, so every
  // chunk comes back with its acknowledgement and the new buffer_free.
  Status write_read(std::uint16_t addr, const std::vector<std::uint16_t>& regs) {
    std::array<std::uint16_t, reg::status_count> r{};
    client_->write_and_read(addr, regs, 0, r);
    return Status::decode(r);
  }

  std::string read_alarm_text() {
    try {
      std::array<std::uint16_t, reg::alarm_text_count> r{};
      client_->read_holding(reg::alarm_text, r);
      return unpack_text(r, 2 * reg::alarm_text_count, true);
    } catch (const std::exception&) {
      return {};
    }
  }

  void check_identity() {
    if (st_.magic != kMagic)
      throw IoError(errc::link_protocol, Place::at_file(peer_),
                    "this Modbus server is not a bezcam program controller (register 0 reads " + hex32(st_.magic) +
                        ", expected 0000425A); check the address");
    if (st_.version != kProtocolVersion)
      throw ControllerError(errc::link_version, Place::at_file(peer_),
                            "the controller speaks protocol version " + std::to_string(st_.version) +
                                ", this sender version " + std::to_string(kProtocolVersion) + "; update one of them");
  }

  void report(bool waiting = false) {
    if (!opt_.on_progress) return;
    StreamProgress p;
    p.bytes_acked = st_.ack_bytes;
    p.bytes_total = prog_.size();
    p.lines_acked = static_cast<std::uint64_t>(
        std::lower_bound(newlines_.begin(), newlines_.end(), std::size_t{st_.ack_bytes}) - newlines_.begin());
    if (st_.ack_bytes == prog_.size()) p.lines_acked = lines_total_;
    p.lines_total = lines_total_;
    p.lines_executed = st_.lines_executed;
    p.seconds = seconds();
    p.rate = p.seconds > 0 ? static_cast<double>(st_.ack_bytes) / p.seconds : 0;
    p.state = st_.state;
    p.reconnects = reconnects_;
    p.waiting = waiting;
    opt_.on_progress(p);
  }

  void event(const std::string& s) {
    if (opt_.on_event) opt_.on_event(s);
  }

  std::string position() const {
    const auto line =
        std::lower_bound(newlines_.begin(), newlines_.end(), std::size_t{st_.ack_bytes}) - newlines_.begin();
    return std::to_string(st_.ack_bytes) + " of " + std::to_string(prog_.size()) + " bytes acknowledged (" +
           std::to_string(line) + " of " + std::to_string(lines_total_) + " lines), " +
           std::to_string(st_.lines_executed) + " lines executed";
  }

  [[noreturn]] void alarm_error() {
    std::string text = read_alarm_text();
    // The line travels as a number (register alarm_line); the text, for
    // people, starts with "line N: " (docs/modbus-register-map.md), which
    // the place already says.
    if (const std::string prefix = "line " + std::to_string(st_.alarm_line) + ": ";
        st_.alarm_line > 0 && text.rfind(prefix, 0) == 0)
      text.erase(0, prefix.size());
    throw ControllerError(errc::controller_alarm,
                          st_.alarm_line > 0 ? Place::at_line(st_.alarm_line) : Place::at_file(peer_),
                          std::string("the controller stopped with alarm ") + to_string(st_.alarm) + " (" +
                              std::to_string(static_cast<int>(st_.alarm)) +
                              "): " + (text.empty() ? "no message" : text) + "; " + position());
  }

  // A request was refused with a Modbus exception: the status says why.
  [[noreturn]] void refused(const ModbusException& e, const std::string& doing) {
    st_ = read_status();
    if (st_.state == State::alarm) alarm_error();
    if (st_.session != session_) restarted();
    throw ControllerError(errc::link_refused, Place::at_file(peer_),
                          std::string("the controller refused ") + doing + " (Modbus exception " +
                              std::to_string(e.code()) + ", reason " + to_string(st_.last_reject) + ": " +
                              describe(st_.last_reject) + "); " + position());
  }

  [[noreturn]] void restarted() {
    throw ControllerError(
        errc::link_restarted, Place::at_file(peer_),
        "the controller no longer holds this transfer: session " + hex32(session_) + " was expected, it reports " +
            (st_.session == 0 ? std::string("no session") : "session " + hex32(st_.session)) + " in state " +
            to_string(st_.state) +
            "; it was restarted or another program was started, so nothing was resumed. Before the loss " +
            std::to_string(acked_high_) + " of " + std::to_string(prog_.size()) +
            " bytes had been acknowledged; check the machine, then stream the program again from the start");
  }

  // Sends a repeatable command (OPEN with this sender's token, COMMIT)
  // until the controller answers it. A refusal goes to `on_refusal`, which
  // reads the status and throws why (losing the connection there counts as
  // a loss); after a lost connection `on_loss` reconnects and says whether
  // the state shows the command got through (true) or it is sent again.
  template <class OnRefusal, class OnLoss>
  void repeat_command(const std::vector<std::uint16_t>& cmd, OnRefusal on_refusal, OnLoss on_loss) {
    for (;;) {
      try {
        st_ = write_read(reg::command, cmd);
        return;
      } catch (const ModbusException& e) {
        try {
          on_refusal(e);
        } catch (const IoError& io) {
          if (on_loss(io.message())) return;
        }
      } catch (const IoError& e) {
        if (on_loss(e.message())) return;
      }
    }
  }

  void open() {
    const auto total = static_cast<std::uint32_t>(prog_.size());
    const auto cmd = encode_command(Command::open, std::array<std::uint32_t, 2>{token_, total});
    const auto refusal = [&](const ModbusException& e) {
      st_ = read_status();
      if (st_.last_reject == Reject::busy)
        throw ControllerError(errc::link_busy, Place::at_file(peer_),
                              "the controller is busy with another sender's program (session " + hex32(st_.session) +
                                  ", state " + to_string(st_.state) + ", " + std::to_string(st_.ack_bytes) + " of " +
                                  std::to_string(st_.total_bytes) +
                                  " bytes received); try again when it is done, or abort it there");
      throw ControllerError(errc::link_refused, Place::at_file(peer_),
                            "the controller refused to open a transfer (Modbus exception " + std::to_string(e.code()) +
                                ", reason " + to_string(st_.last_reject) + ": " + describe(st_.last_reject) + ")");
    };
    // OPEN is repeatable with the same token: reconnect and ask again.
    repeat_command(cmd, refusal, [&](const std::string& why) {
      reconnect_raw(why);
      return false;
    });
    session_ = st_.session;
    event("transfer opened: session " + hex32(session_) + ", controller buffer " + std::to_string(st_.buffer_capacity) +
          " bytes");
    max_chunk_ = std::min<std::uint16_t>(st_.max_chunk, kMaxChunkBytes);
    if (opt_.chunk_bytes > 0) max_chunk_ = std::min(max_chunk_, opt_.chunk_bytes);
    if (max_chunk_ == 0)
      throw ControllerError(errc::link_protocol, Place::at_file(peer_), "the controller announces chunks of 0 bytes");
    mark_progress();
    report();
  }

  // Stall detection looks at both counters: a slow machine with a full
  // buffer still executes lines, a dead one does neither.
  void mark_progress() {
    progress_mark_ = {st_.ack_bytes, st_.lines_executed};
    progress_time_ = Clock::now();
  }

  // Raises if neither bytes nor lines moved for stall_timeout.
  void check_stall() {
    const std::pair<std::uint32_t, std::uint32_t> now{st_.ack_bytes, st_.lines_executed};
    if (now != progress_mark_) {
      progress_mark_ = now;
      progress_time_ = Clock::now();
      return;
    }
    if (Clock::now() - progress_time_ > opt_.stall_timeout)
      throw ControllerError(errc::link_stalled, Place::at_file(peer_),
                            "the controller took no byte and executed no line for " +
                                fmt_num(std::chrono::duration<double>(opt_.stall_timeout).count()) + " s (state " +
                                to_string(st_.state) + "); " + position());
  }

  // Interrupted (Ctrl-C): stop the controller now with ABORT rather than
  // leave it receiving, the spindle on, until its session timeout; then say
  // what it had taken and done.
  void check_cancel() {
    if (!opt_.cancel || !opt_.cancel->load()) return;
    std::string sent_abort = "no transfer was open yet";
    if (session_ != 0) {
      try {
        if (!client_) client_ = connect_(opt_.timeout);
        const auto cmd = encode_command(Command::abort, std::array<std::uint32_t, 2>{token_, session_});
        st_ = write_read(reg::command, cmd);
        sent_abort = "sent ABORT";
      } catch (const std::exception& e) {
        sent_abort = std::string("ABORT could not be sent (") + e.what() +
                     "): the controller keeps the transfer until its session timeout, or an operator's "
                     "stop (abort_controller())";
      }
      try {
        st_ = read_status();
      } catch (const std::exception&) {
      }
    }
    throw ControllerError(errc::link_cancelled, Place::at_file(peer_),
                          "interrupted: " + sent_abort + "; " + position() + ", controller " + to_string(st_.state) +
                              (st_.state == State::alarm ? std::string(" (") + to_string(st_.alarm) + ")" : ""));
  }

  // Polling backs off from 1 ms to 20 ms: quick when the buffer is about
  // to free up, cheap when the machine is slow.
  void poll_wait() {
    std::this_thread::sleep_for(milliseconds(poll_ms_));
    poll_ms_ = std::min(poll_ms_ * 2, 20);
  }

  void send_all() {
    std::uint64_t sent = st_.ack_bytes;
    std::uint32_t seq = st_.ack_seq;
    while (sent < prog_.size()) {
      check_cancel();
      try {
        if (st_.state == State::alarm) alarm_error();
        if (st_.session != session_) restarted();
        const std::size_t want = std::min<std::size_t>(max_chunk_, prog_.size() - sent);
        // Never more than the controller said it can take (flow control);
        // a nearly full buffer is waited for rather than fed in crumbs.
        if (st_.buffer_free < std::min<std::size_t>(want, 64)) {
          report(true);
          check_stall();
          poll_wait();
          st_ = read_status();
          continue;
        }
        // Chunks start at the controller's acknowledged position and are
        // numbered from its acknowledged sequence: after a resume both come
        // from the controller, so nothing is skipped and nothing doubled.
        const std::size_t n = std::min<std::size_t>(want, st_.buffer_free);
        const auto regs = encode_chunk({session_, seq + 1, prog_.substr(sent, n)});
        sent_high_ = std::max<std::uint64_t>(sent_high_, sent + n);
        st_ = write_read(reg::chunk, regs);
        // The acknowledgement must account for exactly this chunk; anything
        // else means the two sides disagree about the program.
        if (st_.ack_seq != seq + 1 || st_.ack_bytes != sent + n)
          throw ControllerError(errc::link_ack, Place::at_file(peer_),
                                "chunk " + std::to_string(seq + 1) + " was acknowledged as sequence " +
                                    std::to_string(st_.ack_seq) + " at byte " + std::to_string(st_.ack_bytes) +
                                    ", expected byte " + std::to_string(sent + n) + "; the program may be corrupted");
        ++seq;
        sent += n;
        ++chunks_;
        acked_high_ = std::max<std::uint64_t>(acked_high_, st_.ack_bytes);
        failures_ = 0;  // progress: the reconnection budget starts afresh
        poll_ms_ = 1;
        check_stall();
        report();
      } catch (const ModbusException& e) {
        try {
          st_ = read_status();
          if (st_.last_reject == Reject::not_owner && st_.session == session_)
            resume();  // our connection was replaced or evicted: take the transfer back
          else if (st_.last_reject != Reject::buffer_full)  // buffer-full: raced with the executor, wait
            refused(e, "chunk " + std::to_string(seq + 1));
        } catch (const IoError& io) {
          reconnect(io.message());
        }
        sent = st_.ack_bytes;
        seq = st_.ack_seq;
      } catch (const IoError& e) {
        reconnect(e.message());
        sent = st_.ack_bytes;
        seq = st_.ack_seq;
      }
    }
  }

  // COMMIT is idempotent on the controller, so a COMMIT whose reply was
  // lost is either visible in the state after reconnecting (FINISHING or
  // DONE) or simply sent again.
  void commit() {
    const auto cmd =
        encode_command(Command::commit,
                       std::array<std::uint32_t, 4>{token_, session_, static_cast<std::uint32_t>(prog_.size()), crc_});
    repeat_command(
        cmd, [&](const ModbusException& e) { refused(e, "COMMIT (length and CRC-32 check)"); },
        [&](const std::string& why) {
          reconnect(why);
          if (st_.state == State::finishing || st_.state == State::done) return true;  // it got through
          if (st_.ack_bytes != prog_.size())
            throw ControllerError(errc::link_ack, Place::at_file(peer_),
                                  "after reconnecting before COMMIT the controller reports " + position() +
                                      "; the program may be corrupted");
          return false;
        });
    event("controller confirmed length " + std::to_string(prog_.size()) + " bytes and CRC-32 " + hex32(crc_));
    report();
  }

  void wait_done() {
    poll_ms_ = 1;
    mark_progress();
    while (st_.state != State::done) {
      check_cancel();
      if (st_.state == State::alarm) alarm_error();
      if (st_.session != session_) restarted();
      check_stall();
      poll_wait();
      try {
        st_ = read_status();
      } catch (const IoError& e) {
        reconnect(e.message());
      }
      report();
    }
    report();
  }

  // Replaces the connection; throws IoError when the budget is spent. The
  // budget counts attempts since the last acknowledged progress, so a link
  // that keeps failing without letting a byte through ends in bounded time,
  // while a long transfer may survive many separate outages.
  void reconnect_raw(const std::string& why) {
    client_.reset();
    event("connection lost (" + why + "); reconnecting");
    const auto deadline = Clock::now() + opt_.retry_time;
    for (int attempt = 1;; ++attempt) {
      check_cancel();
      if (failures_ >= opt_.retries || Clock::now() >= deadline)
        throw IoError(errc::link_lost, Place::at_file(peer_),
                      "the connection was lost and could not be restored (" + std::to_string(failures_) +
                          " attempts, last: " + why + "); " + std::to_string(acked_high_) + " of " +
                          std::to_string(prog_.size()) +
                          " bytes had been acknowledged. The controller keeps the transfer until its session "
                          "timeout; check the link and stream again");
      ++failures_;
      if (attempt > 1) {  // back off: 50, 100, 200 ... 1000 ms, within the deadline
        const auto wait = milliseconds(std::min(1000, 50 << std::min(attempt - 2, 5)));
        std::this_thread::sleep_for(
            std::min<milliseconds>(wait, std::chrono::duration_cast<milliseconds>(deadline - Clock::now())));
      }
      try {
        client_ = connect_(opt_.timeout);
        st_ = read_status();
        check_identity();
        ++reconnects_;
        return;
      } catch (const IoError&) {
        client_.reset();
      }
    }
  }

  void resume() {
    const auto cmd = encode_command(Command::resume, std::array<std::uint32_t, 2>{token_, session_});
    try {
      st_ = write_read(reg::command, cmd);
    } catch (const ModbusException& e) {
      refused(e, "RESUME");
    }
    if (st_.ack_bytes > sent_high_)
      throw ControllerError(errc::link_ack, Place::at_file(peer_),
                            "after reconnecting the controller reports " + position() +
                                ", more than was sent; the program may be corrupted");
  }

  // Reconnect, then decide: the same session is resumed from the
  // controller's position; any other session (0 after a restart, or another
  // sender's program) is a lost transfer and is never written into.
  void reconnect(const std::string& why) {
    for (;;) {
      reconnect_raw(why);
      if (st_.session != session_) restarted();
      try {
        resume();
        break;
      } catch (const IoError&) {
        continue;  // lost again while resuming: next attempt
      }
    }
    event("reconnected; resuming at byte " + std::to_string(st_.ack_bytes) + " (chunk " +
          std::to_string(st_.ack_seq + 1) + "), controller " + to_string(st_.state));
    report();
  }

  std::string_view prog_;
  const TransportFactory& connect_;
  std::string peer_;
  const StreamOptions& opt_;
  std::uint32_t crc_ = 0, token_ = 0, session_ = 0;
  std::vector<std::size_t> newlines_;
  std::uint64_t lines_total_ = 0, chunks_ = 0, acked_high_ = 0, sent_high_ = 0;
  std::unique_ptr<Transport> client_;
  Status st_;
  std::uint16_t max_chunk_ = kMaxChunkBytes;
  int reconnects_ = 0, failures_ = 0, poll_ms_ = 1;
  Clock::time_point start_, progress_time_;
  std::pair<std::uint32_t, std::uint32_t> progress_mark_{0, 0};
};

}  // namespace

namespace {

ControllerReport report_of(Transport& c) {
  ControllerReport r;
  std::array<std::uint16_t, reg::status_count> st{};
  c.read_holding(0, st);
  r.status = Status::decode(st);
  if (r.status.magic != kMagic) return r;
  std::array<std::uint16_t, reg::alarm_text_count> at{};
  c.read_holding(reg::alarm_text, at);
  r.alarm_text = unpack_text(at, 2 * reg::alarm_text_count, true);
  std::array<std::uint16_t, reg::machine_name_count> mn{};
  c.read_holding(reg::machine_name, mn);
  r.machine = unpack_text(mn, 2 * reg::machine_name_count, true);
  return r;
}

void require_bezcam(const ControllerReport& r, const Endpoint& to) {
  if (r.status.magic != kMagic)
    throw IoError(
        errc::link_protocol, Place::at_file(to.str()),
        "this Modbus server is not a bezcam program controller (register 0 reads " + hex32(r.status.magic) + ")");
}

}  // namespace

ControllerReport controller_status(const Endpoint& to, std::chrono::milliseconds timeout) {
  ModbusClient c(to, timeout);
  ControllerReport r = report_of(c);
  require_bezcam(r, to);
  return r;
}

ControllerReport abort_controller(const Endpoint& to, std::chrono::milliseconds timeout) {
  ModbusClient c(to, timeout);
  ControllerReport r = report_of(c);
  require_bezcam(r, to);
  const State s = r.status.state;
  if (s != State::receiving && s != State::finishing) return r;
  // Token 0: the operator's stop, accepted for the open session whoever
  // opened it (stopping is always safe; starting needs the token).
  const auto cmd = encode_command(Command::abort, std::array<std::uint32_t, 2>{0, r.status.session});
  try {
    c.write_registers(reg::command, cmd);
  } catch (const ModbusException& e) {
    throw ControllerError(errc::link_refused, Place::at_file(to.str()),
                          std::string("the controller refused ABORT: ") + e.what());
  }
  return report_of(c);
}

StreamResult stream_program(std::string_view program, const Endpoint& to, const StreamOptions& opt) {
  return stream_program(program, modbus_transport(to), to.str(), opt);
}

StreamResult stream_program(std::string_view program, const TransportFactory& connect, const std::string& peer,
                            const StreamOptions& opt) {
  if (program.empty()) throw InputError(errc::link_empty, Place{}, "the program is empty; nothing to send");
  if (program.size() > std::numeric_limits<std::uint32_t>::max())
    throw InputError(errc::link_too_large, Place{}, "the program is larger than 4 GiB, the protocol's limit");
  if (const auto nul = program.find('\0'); nul != std::string_view::npos) {
    const auto line = 1 + std::count(program.begin(), program.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    throw InputError(errc::link_nul_byte, Place::at_line(line),
                     "the program holds a NUL byte (offset " + std::to_string(nul) + "); G-code is text");
  }
  if (opt.retries < 0 || opt.timeout.count() <= 0 || opt.stall_timeout.count() <= 0)
    throw InputError(errc::link_options, Place{}, "timeouts must be positive and retries not negative");
  return Sender(program, connect, peer, opt).run();
}

}  // namespace bezcam::link
