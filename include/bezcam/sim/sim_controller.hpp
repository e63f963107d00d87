#pragma once
/// The simulated controller: the protocol state machine of
/// docs/modbus-register-map.md, a bounded receive buffer, and an executor
/// that runs complete lines through the shared G-code interpreter while the
/// program is still arriving (drip feed), enforcing the profile's travel and
/// feed limits, and writing the deterministic trace (trace.hpp).
///
/// It is a library class with no socket of its own: ModbusServer
/// (sim_server.hpp) feeds it raw Modbus TCP requests over real sockets, and
/// run_program() pushes a file through the very same buffer and executor,
/// so a program gives the same trace either way.
///
/// Thread-safe: any number of connection threads may call handle_frame()
/// concurrently; one internal thread executes.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "bezcam/gcode/reader.hpp"
#include "bezcam/link/crc32.hpp"
#include "bezcam/link/register_map.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/sim/machine_pace.hpp"
#include "bezcam/verify/stock_cutter.hpp"

namespace bezcam::sim {

// The register map and frame layouts are the link's (bezcam/link/).
using namespace bezcam::link;

/// Receives the trace as it is produced. `restart` is true for the first
/// record of a new program (a file sink truncates there). Called from the
/// executor thread only; a sink that writes a file should flush each call,
/// so that the trace on disk is complete whenever the state says DONE.
using TraceSink = std::function<void(std::string_view text, bool restart)>;

/// Identifies one client connection (assigned by connection_opened()).
using ConnId = std::uint64_t;

/// The workpiece on the simulated machine (docs/cli.md, "The stock"):
/// every executed move is cut into it, as `bezcam verify` cuts a
/// program, and it is kept from program to program until the controller
/// stops. Lengths are millimetres whatever the programs' units.
struct StockConfig {
  StockBox box;
  double cell = 0;
  /// The tools, by T number; a move with a tool the table lacks is refused
  /// (alarm gcode, error verify.tool, at its line) before anything is cut.
  StockTools tools;
  StockCutterOptions options;
};

struct ControllerConfig {
  /// Travel limits, maximum feed and the machine name in the trace.
  MachineProfile profile;
  /// Receive buffer, bytes: at least kMaxChunkBytes, at most 65535 (the
  /// width of register buffer_free). A program line longer than this is
  /// refused (alarm line-too-long).
  std::size_t buffer_bytes = 4096;
  /// An open transfer whose owner has sent nothing for this long is
  /// stopped with alarm sender-lost (the owner may RESUME until then).
  std::chrono::milliseconds session_timeout{30000};
  /// Time the executor spends per program line: a slow controller.
  std::chrono::microseconds exec_delay{0};
  /// Machine pace (docs/motion.md): > 0 executes with the profile's
  /// motion model at this multiple of real time (1: real time), the
  /// program draining from the buffer only as the machine moves through
  /// it, and counts the stalls when the buffer runs dry mid-program
  /// (status registers starved_ms and stalls, the operator's log). The
  /// executor reads ahead of the machine (its look-ahead window); the
  /// status, the trace, an alarm's line and DONE follow the machine. 0 (the
  /// default, and `--time-scale max`): as fast as the CPU allows. Needs a
  /// profile with a motion model.
  double time_scale = 0;
  /// Session id of the first transfer, the next ones counting up; 0 draws
  /// them at random (the default: a restarted controller must not reuse
  /// the id of the transfer it lost). Fixed values are for tests and docs.
  std::uint32_t first_session = 0;
  /// Fault injection: the N-th chunk write received (1-based, counting
  /// every chunk request, retransmissions included) makes the connection
  /// drop, before the chunk is applied or after it is applied but before
  /// the reply is sent. Each number fires once.
  std::vector<std::uint64_t> drop_before_chunk, drop_after_chunk;
  /// Fault injection: the N-th chunk write, once validated, has its first
  /// digit changed before it is stored, as faulty memory would: the chunk
  /// is acknowledged, and only the whole-program CRC-32 can catch it.
  std::vector<std::uint64_t> corrupt_chunk;
  /// Where the trace goes (may be empty).
  TraceSink trace;
  /// The stock to cut; none by default. After each program's final record
  /// (done, alarm, stopped) the trace gets the stock's record.
  std::optional<StockConfig> stock;
  /// The operator's log (`simulate --listen` prints it on stderr): one
  /// line per event, connections opened and closed, programs opened,
  /// completed and stopped by an alarm. Called with the controller's lock
  /// held, from any thread: it must not call back into the controller.
  std::function<void(const std::string& event)> on_event;
  /// Test hook: every program line as the executor takes it, in order.
  std::function<void(long line, std::string_view text)> on_line;
};

/// What the connection layer does with a request.
struct FrameReply {
  int exception = 0;                ///< Modbus exception code; 0 for a normal reply
  std::uint16_t read_addr = 0;      ///< first register of `regs`
  std::vector<std::uint16_t> regs;  ///< values read (FC 03, 04, 23)
  bool read_input = false;          ///< `regs` are input registers (FC 04)
  bool drop = false;                ///< close the connection without a reply (fault injection)
};

/// Bounds of the simulated machine.
inline constexpr std::size_t kMinBuffer = kMaxChunkBytes, kMaxBuffer = 65535;

class SimController {
 public:
  /// Throws InputError("sim.config", ...) for a buffer outside
  /// [kMinBuffer, kMaxBuffer] or a non-positive session timeout, and for a
  /// stock what StockCutter refuses (stock.box, stock.cell, stock.memory),
  /// before the grid is allocated.
  explicit SimController(ControllerConfig cfg);
  /// Stops the executor (the trace is complete up to the last executed line).
  ~SimController();
  SimController(const SimController&) = delete;
  SimController& operator=(const SimController&) = delete;

  /// Connection bookkeeping for the server.
  ConnId connection_opened();
  void connection_closed(ConnId c);
  /// The connection that owns the open transfer, 0 when none.
  ConnId owner() const;

  /// Handles one Modbus TCP request as received (MBAP header + PDU, at
  /// most 260 bytes). Never throws for any input; malformed frames get an
  /// exception reply or `drop`.
  FrameReply handle_frame(ConnId c, std::span<const std::uint8_t> adu);

  /// Executes a whole program through the same buffer, checks and executor
  /// as a streamed one, with no network; blocks until DONE or ALARM (or
  /// stop()). Refused (returns with the alarm, or throws InputError
  /// "sim.busy") while a streamed transfer is open.
  Status run_program(std::string_view program);

  /// The status block as connection `c` reads it.
  Status status(ConnId c = 0) const;
  /// The current alarm's text for people, as register alarm_text holds it:
  /// "line N: " (when the alarm has a line) and the message ("" when none).
  std::string alarm_text() const;
  /// The current alarm's message alone; its line is status().alarm_line.
  std::string alarm_message() const;
  /// The error id of the current alarm (e.g. `gcode.travel`,
  /// `verify.tool`; "" when none).
  std::string alarm_id() const;
  /// Waits until the program is DONE or in ALARM and the trace holds its
  /// final record; false after `timeout`.
  bool wait_final(std::chrono::milliseconds timeout) const;
  /// Stops the executor after the line in progress (at machine pace the
  /// machine stops where it is, and the trace ends with the last line it
  /// finished); the trace is flushed. Idempotent.
  void stop();

 private:
  struct Pending;  // an alarm waiting for the executor to trace it
  void log_locked(const std::string& event) const;
  Reject command_locked(ConnId c, std::span<const std::uint16_t> regs);
  Reject chunk_locked(ConnId c, std::span<const std::uint16_t> regs, bool corrupt);
  Reject apply_chunk_locked(ConnId c, std::uint32_t session, std::uint32_t seq, std::string_view payload,
                            std::uint32_t crc);
  void open_locked(ConnId c, std::uint32_t token, std::uint32_t total);
  /// Stops the program at once with alarm `a` at `line` (kMachineLine:
  /// the line the machine had reached).
  void raise_alarm_locked(Alarm a, long line, std::string id, std::string message);
  /// Enters ALARM with alarm `a` at `line` (0: none) and `message`, and
  /// logs it; the caller sees to the trace.
  void record_alarm_locked(Alarm a, long line, std::string id, std::string message);
  std::string alarm_text_locked() const;
  static constexpr long kMachineLine = -1;
  std::uint32_t next_session_locked();
  std::size_t buffered_locked() const { return buf_.size() - head_; }
  Status status_locked(ConnId c) const;
  std::vector<std::uint16_t> read_locked(ConnId c, std::uint16_t addr, std::uint16_t n) const;
  void exec_loop();
  void emit_trace(const std::string& text, bool restart);
  void execute_line(std::unique_lock<std::mutex>& lk, GcodeInterpreter& interp, std::uint64_t cur_epoch,
                    std::size_t nl);
  void finish_program(std::unique_lock<std::mutex>& lk, GcodeInterpreter& interp, std::uint64_t cur_epoch);
  // Machine pace: the end of the program in two steps (the interpreter's
  // last blocks go to the machine, then DONE once it has run them), and a
  // refused line raised once the machine has run everything before it.
  void finish_interpreter(std::unique_lock<std::mutex>& lk, GcodeInterpreter& interp, std::uint64_t cur_epoch);
  void finish_paced(std::unique_lock<std::mutex>& lk, const GcodeInterpreter& interp, std::uint64_t cur_epoch);
  void raise_failure(std::unique_lock<std::mutex>& lk, std::uint64_t cur_epoch);

  ControllerConfig cfg_;
  mutable std::mutex m_;
  mutable std::condition_variable cv_;
  bool stop_ = false;

  // Transfer (guarded by m_).
  State state_ = State::idle;
  std::uint64_t epoch_ = 0;  // program generation: the executor restarts on change
  std::uint32_t session_ = 0, token_ = 0, total_ = 0, last_session_ = 0;
  ConnId owner_ = 0, next_conn_ = 1;
  std::chrono::steady_clock::time_point owner_seen_{};
  std::uint32_t ack_seq_ = 0, ack_bytes_ = 0;
  Crc32 crc_;
  bool committed_ = false;
  std::uint32_t commit_total_ = 0, commit_crc_ = 0;
  std::string buf_;  // receive buffer: bytes [head_, size) are pending
  std::size_t head_ = 0;
  struct Recent {
    std::uint32_t seq = 0, crc = 0;
    std::uint16_t len = 0;
  };
  std::vector<Recent> recent_;  // ring of the last chunks applied (retransmission check)
  std::uint64_t chunk_requests_ = 0;
  std::uint32_t duplicates_ = 0, rejects_ = 0;
  std::map<ConnId, Reject> last_reject_;
  std::size_t connections_ = 0;

  // Results of execution (guarded by m_, written by the executor).
  Alarm alarm_ = Alarm::none;
  std::uint32_t alarm_line_ = 0;
  std::string alarm_message_;  // without its line
  std::string alarm_id_;
  std::unique_ptr<Pending> pending_alarm_;
  bool final_traced_ = false;
  long line_no_ = 0, lines_done_ = 0, blocks_done_ = 0;
  MachineState machine_;
  // Machine pace (executor thread; the figures guarded by m_).
  std::unique_ptr<MachinePace> pace_;
  std::chrono::steady_clock::time_point pace_origin_{};
  bool pace_started_ = false, pace_stalled_ = false;
  double stall_from_ = 0;  // machine time the machine ran dry
  std::uint32_t starved_ms_ = 0, stalls_ = 0;
  double pace_now() const;  // machine time now
  // At machine pace the interpreter reads ahead of the machine; what is
  // reported (status registers, trace, an alarm's line, DONE) is what the
  // machine has done. The lines read and not yet done, in order:
  // The stock (sim_controller_stock.cpp): a move with the tool and units
  // it was executed with.
  struct StockMove {
    MotionBlock block;
    int tool = 0;
    Units units = Units::mm;
  };
  std::unique_ptr<StockCutter> stock_;  // the executor's own
  std::vector<StockMove> stock_queue_;  // moves the machine finished, not yet cut (guarded by m_)
  // Refuses (verify.tool) blocks whose tool the stock's table lacks.
  void check_stock_tools(const std::vector<MotionBlock>& blocks, const MachineState& s) const;
  std::vector<StockMove> stock_moves(const std::vector<MotionBlock>& blocks, const MachineState& s) const;
  // Cuts the blocks executed with state `s` (checked first: nothing is
  // cut when one is refused). Executor thread, unlocked.
  void cut_stock(const std::vector<MotionBlock>& blocks, const MachineState& s);
  void cut_moves(const std::vector<StockMove>& moves);
  std::vector<StockMove> take_stock_locked();
  // Cuts `moves`, then the stock's trace record ("" without a stock).
  // Executor thread, unlocked.
  std::string stock_record(const std::vector<StockMove>& moves = {});
  struct Ahead {
    long line = 0;
    bool counts = true;           // a program line (false: the blocks the interpreter's finish() released)
    MachineState after;           // the state once it is executed
    std::string trace;            // its trace records
    std::vector<StockMove> cuts;  // its moves, cut once the machine has run them
  };
  std::deque<Ahead> ahead_;
  long settled_ = 0;           // every block of the lines up to here has been read
  long retired_settled_ = -1;  // settled_ when lines were last retired
  long last_block_line_ = 0;   // the line of the last block read
  // A line the executor refused (or could not read) at machine pace: the
  // alarm is raised when the machine has run everything before it.
  struct Failure {
    Alarm alarm = Alarm::none;
    long line = 0;
    std::string id;       // the alarm's error id
    std::string message;  // the alarm's message (its line is `line`)
    std::string trace;    // its trace record
  };
  std::optional<Failure> failure_;
  bool interp_finished_ = false;  // the interpreter's finish() was run
  // What the machine has done at machine time t.
  struct MachineView {
    MachineState state;  // modal state of the line in progress, position on the planned path
    long lines = 0, blocks = 0;
    long done_line = 0;  // every line up to here is done
    long reached = 0;    // the line in progress, or done_line when the machine is at rest
  };
  bool paced_locked() const;
  void reset_paced_locked();
  MachineView view_locked(double t) const;
  // Moves the lines done by machine time t (all of them: `all`) out of
  // ahead_ into the retired state; returns their trace records.
  std::string retire_locked(double t, bool all);
  // The machine stops where it is: what it finished is retired (its
  // trace records into `trace`), what was read ahead dropped.
  MachineView freeze_locked(std::string& trace);
  // Steps of the executor at machine pace; true when it acted (the loop
  // starts over). retire_step: finished lines traced; machine_step: the
  // machine takes work from the window, stalls, or reaches a refused line
  // (`wake`: when it needs work next).
  bool retire_step(std::unique_lock<std::mutex>& lk);
  bool machine_step(std::unique_lock<std::mutex>& lk, std::uint64_t cur_epoch, bool line_ready,
                    std::optional<std::chrono::steady_clock::time_point>& wake);
  // A line is about to be read: the machine starts, or ends a stall.
  void machine_fed_locked();
  void read_ahead_locked(const GcodeInterpreter& interp, std::uint64_t cur_epoch, long no, const MachineState& before,
                         const std::vector<MotionBlock>& blocks,
                         const std::optional<std::pair<Alarm, std::string>>& failed, const std::string& id,
                         std::string text);

  std::thread exec_;
};

}  // namespace bezcam::sim
