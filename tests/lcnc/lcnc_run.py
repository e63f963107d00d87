#!/usr/bin/python3
"""Run one G-code program on real LinuxCNC 2.9 (headless) and time it.

    /usr/bin/python3 tests/lcnc/lcnc_run.py --profile machines/linuxcnc.json \
        PROGRAM.ngc [--out DIR]

The machine is configured from the profile's `motion` object (a profile
without one is refused): per-axis MAX_VELOCITY / MAX_ACCELERATION, [TRAJ]
limits, servo and trajectory period, ARC_BLEND_OPTIMIZATION_DEPTH =
lookahead_blocks, and an MDI `G64 P<blend_tolerance_mm> Q0` before the
program as the default path mode (a G64/G61 in the program wins). Motion
keys LinuxCNC cannot be set to (jerk, a segment cap other than its own
1.02 periods, a block rate other than one per period, tool change or
spindle start times) make the run refuse rather than compare unlike things.

The cycle time is counted in planner periods: the HAL sampler records the
commanded position every servo period; the cycle runs from the last sample
at rest before the first motion to the first sample at rest after the last
motion. LinuxCNC runs in real time (uspace, POSIX non-realtime), so a run
takes its program's duration plus about 2.5 s of start and stop.

Prints one JSON object (cycle_time_s, feed_time_s, rapid_time_s, ...); with
--out, also writes DIR/samples.tsv (t x y z v line type, one row per period
of the cycle window) and DIR/summary.json. Exit status: 0 ran, 1 LinuxCNC
or the program failed, 2 refused (usage, profile), 3 LinuxCNC not installed.
Runs are serialised with a lock file; every process started is ended.
"""
import argparse
import fcntl
import json
import os
import pwd
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
LOCK = "/tmp/lcnc-run.lock"  # the same lock as ../shared/tools/lcnc-run: one LinuxCNC at a time
LCNC_LOCK = "/tmp/linuxcnc.lock"
LCNC_NAMES = ("rtapi_app", "milltask", "io", "halsampler", "linuxcncsvr")
# LinuxCNC 2.9's own figures the profile must match (not settable in the INI)
LCNC_MIN_SEGMENT_PERIODS = 1.02
# motion-type pin values (emcmot): traverse, feed, arc
TYPE_RAPID, TYPE_FEED, TYPE_ARC = 1, 2, 3


class Refused(Exception):
    pass


def installed():
    return shutil.which("linuxcnc", path="/usr/bin:/bin") is not None and \
        shutil.which("halsampler", path="/usr/bin:/bin") is not None


def motion_of(profile_path):
    """The profile's motion object, checked against what LinuxCNC can be."""
    with open(profile_path) as f:
        prof = json.load(f)
    m = prof.get("motion")
    if not isinstance(m, dict):
        raise Refused("%s has no 'motion' object: the anchor configures LinuxCNC from "
                      "it (docs/linuxcnc-anchor.md)" % profile_path)
    need = ("max_velocity_mm_min", "max_acceleration_mm_s2", "period_s",
            "lookahead_blocks", "blend_tolerance_mm")
    missing = [k for k in need if k not in m]
    if missing:
        raise Refused("%s: motion lacks %s" % (profile_path, ", ".join(missing)))
    for k in ("max_velocity_mm_min", "max_acceleration_mm_s2"):
        if any(a not in m[k] or not m[k][a] > 0 for a in "xyz"):
            raise Refused("%s: motion.%s needs x, y, z > 0" % (profile_path, k))
    period = float(m["period_s"])
    if not 0 < period <= 0.01:
        raise Refused("%s: motion.period_s %g out of range" % (profile_path, period))
    if m.get("max_jerk_mm_s3") is not None:
        raise Refused("%s: LinuxCNC 2.9's planner is trapezoidal, it has no jerk limit"
                      % profile_path)
    msp = m.get("min_segment_periods", LCNC_MIN_SEGMENT_PERIODS)
    if abs(msp - LCNC_MIN_SEGMENT_PERIODS) > 1e-9:
        raise Refused("%s: min_segment_periods %g, LinuxCNC 2.9's is fixed at %g"
                      % (profile_path, msp, LCNC_MIN_SEGMENT_PERIODS))
    rate = m.get("block_rate_hz")
    if rate is not None and abs(rate * period - 1) > 1e-6:
        raise Refused("%s: block_rate_hz %g, LinuxCNC starts at most one block per "
                      "period (%g Hz)" % (profile_path, rate, 1 / period))
    for k in ("tool_change_s", "spindle_start_s"):
        if m.get(k, 0):
            raise Refused("%s: %s %g, the simulated LinuxCNC takes none"
                          % (profile_path, k, m[k]))
    if m["blend_tolerance_mm"] < 0:
        raise Refused("%s: blend_tolerance_mm < 0" % profile_path)
    return m


def ini_text(m, driver, hal):
    vel = {a: m["max_velocity_mm_min"][a] / 60.0 for a in "xyz"}
    acc = {a: float(m["max_acceleration_mm_s2"][a]) for a in "xyz"}
    period_ns = int(round(m["period_s"] * 1e9))
    out = ["[EMC]", "VERSION = 1.1", "MACHINE = bezcam-anchor", "",
           "[DISPLAY]", "DISPLAY = " + driver, "", 
           "[TASK]", "TASK = milltask", "CYCLE_TIME = %g" % m["period_s"], "",
           "[RS274NGC]", "PARAMETER_FILE = anchor.var",
           "RS274NGC_STARTUP_CODE = G21 G17 G90 G94 G40 G49 G80 G54", "",
           "[EMCMOT]", "EMCMOT = motmod", "COMM_TIMEOUT = 1.0",
           "SERVO_PERIOD = %d" % period_ns, "",
           "[EMCIO]", "EMCIO = io", "CYCLE_TIME = %g" % m["period_s"],
           "TOOL_TABLE = tool.tbl", "",
           "[HAL]", "HALFILE = " + hal, "",
           "[TRAJ]", "COORDINATES = X Y Z", "LINEAR_UNITS = mm", "ANGULAR_UNITS = degree",
           "DEFAULT_LINEAR_VELOCITY = %.6f" % max(vel.values()),
           "MAX_LINEAR_VELOCITY = %.6f" % max(vel.values()),
           "DEFAULT_LINEAR_ACCELERATION = %.6f" % max(acc.values()),
           "MAX_LINEAR_ACCELERATION = %.6f" % max(acc.values()),
           "ARC_BLEND_ENABLE = 1", "ARC_BLEND_FALLBACK_ENABLE = 0",
           "ARC_BLEND_OPTIMIZATION_DEPTH = %d" % int(m["lookahead_blocks"]),
           "ARC_BLEND_GAP_CYCLES = 4", "ARC_BLEND_RAMP_FREQ = 100",
           "NO_FORCE_HOMING = 1", "",
           "[KINS]", "KINEMATICS = trivkins coordinates=XYZ", "JOINTS = 3", ""]
    for j, a in enumerate("xyz"):
        limits = ["MAX_VELOCITY = %.6f" % vel[a], "MAX_ACCELERATION = %.6f" % acc[a],
                  "MIN_LIMIT = -2000", "MAX_LIMIT = 2000"]
        out += ["[AXIS_%s]" % a.upper()] + limits + [""]
        out += ["[JOINT_%d]" % j, "TYPE = LINEAR", "HOME = 0", "HOME_OFFSET = 0",
                "HOME_SEARCH_VEL = 0", "HOME_LATCH_VEL = 0", "HOME_SEQUENCE = 0",
                "FERROR = 1000", "MIN_FERROR = 1000"] + limits + [""]
    return "\n".join(out)


HAL = """\
loadrt [KINS]KINEMATICS
loadrt [EMCMOT]EMCMOT servo_period_nsec=[EMCMOT]SERVO_PERIOD num_joints=[KINS]JOINTS
# columns: x y z current-vel program-line motion-type servo-period
loadrt sampler depth=%d cfg=ffffssu
addf motion-command-handler servo-thread
addf motion-controller servo-thread
addf sampler.0 servo-thread
# a period counter: integ.0.out grows by 1 every servo period
loadrt integ count=1
addf integ.0 servo-thread
setp integ.0.in %.9f
net jx joint.0.motor-pos-cmd => joint.0.motor-pos-fb
net jy joint.1.motor-pos-cmd => joint.1.motor-pos-fb
net jz joint.2.motor-pos-cmd => joint.2.motor-pos-fb
net estop iocontrol.0.user-enable-out => iocontrol.0.emc-enable-in
net tprep iocontrol.0.tool-prepare => iocontrol.0.tool-prepared
net tchg iocontrol.0.tool-change => iocontrol.0.tool-changed
net sx axis.x.pos-cmd => sampler.0.pin.0
net sy axis.y.pos-cmd => sampler.0.pin.1
net sz axis.z.pos-cmd => sampler.0.pin.2
net sv motion.current-vel => sampler.0.pin.3
net sl motion.program-line => sampler.0.pin.4
net st motion.motion-type => sampler.0.pin.5
net sp motion.servo.last-period => sampler.0.pin.6
setp sampler.0.enable 0
"""


def started_at(pid):
    """Start time of a process in clock ticks since boot (None if gone)."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            return int(f.read().rsplit(")", 1)[1].split()[19])
    except (OSError, IndexError, ValueError):
        return None


def boot_ticks_now():
    with open("/proc/uptime") as f:
        return int(float(f.read().split()[0]) * os.sysconf("SC_CLK_TCK"))


def foreign_linuxcnc():
    found = []
    for pid in os.listdir("/proc"):
        if pid.isdigit():
            try:
                with open("/proc/%s/comm" % pid) as f:
                    if f.read().strip() in LCNC_NAMES:
                        found.append(int(pid))
            except OSError:
                pass
    return found


def start_and_wait(rundir, ini, program, mdi, timeout):
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "INI_FILE_NAME")}
    env.update(PATH="/usr/bin:/bin:/usr/sbin:/sbin", HOME=rundir, LCNC_RUN_DIR=rundir,
               LCNC_RUN_PROGRAM=program, LCNC_RUN_MDI=";".join(mdi),
               LCNC_RUN_TIMEOUT=str(timeout))
    rtdir = None
    if os.geteuid() == 0:
        # uspace rtapi_app refuses root without a fallback uid; its FIFO directory
        # must belong to that uid
        nobody = pwd.getpwnam("nobody")
        rtdir = tempfile.mkdtemp(prefix="bezcam-lcnc-rt.")
        os.chown(rtdir, nobody.pw_uid, nobody.pw_gid)
        env.update(RTAPI_UID=str(nobody.pw_uid),
                   RTAPI_FIFO_PATH=os.path.join(rtdir, "fifo"))
    log = open(os.path.join(rundir, "linuxcnc.log"), "w")
    t_start = boot_ticks_now() - 1
    proc = subprocess.Popen(["linuxcnc", "-r", ini], cwd=rundir, env=env,
                            stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                            start_new_session=True)
    try:
        try:
            rc = proc.wait(timeout=timeout + 90)
        except (subprocess.TimeoutExpired, KeyboardInterrupt) as ex:
            # too long, or we are interrupted: stop LinuxCNC before leaving
            proc.send_signal(signal.SIGTERM)  # the script's trap runs LinuxCNC's Cleanup
            try:
                rc = proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                rc = proc.wait()
            if isinstance(ex, KeyboardInterrupt):
                raise
    finally:
        log.close()
        # rtapi_app (its own session) leaves after the script: poll until no
        # LinuxCNC process is left. None ran when this run began (checked under
        # the lock), so those still there were started by it.
        end = time.monotonic() + 30
        while (foreign_linuxcnc() or os.path.exists(LCNC_LOCK)) and time.monotonic() < end:
            time.sleep(0.01)
        left = [p for p in foreign_linuxcnc() if (started_at(p) or -1) >= t_start]
        for pid in left:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        if os.path.exists(LCNC_LOCK) and not foreign_linuxcnc():
            os.remove(LCNC_LOCK)
        if rtdir:
            shutil.rmtree(rtdir, ignore_errors=True)
    if left:
        raise RuntimeError("LinuxCNC left processes %s running 30 s after its exit "
                           "(killed)" % left)
    return rc


def read_samples(path):
    rows = []
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) == 8:
                rows.append((int(p[0]), float(p[1]), float(p[2]), float(p[3]),
                             float(p[4]), int(p[5]), int(p[6]), int(p[7])))
    return rows


def late_invocations(rows, first, last):
    """Servo-thread invocations inside the cycle window that came late: the
    interval since the one before (motion.servo.last-period, in CPU clocks)
    more than 1.5 times the run's median. Returns (how many, periods missed)."""
    periods = [r[7] for r in rows if len(r) > 7 and r[7] > 0]
    if len(periods) < 3:
        return 0, 0
    med = sorted(periods)[len(periods) // 2]
    late = [r[7] / med for r in rows[first + 1:last + 1] if len(r) > 7 and r[7] > 1.5 * med]
    return len(late), int(sum(round(x) - 1 for x in late))


def analyse(rows, period):
    """Cycle window and split. rows: (n, x, y, z, v, line, type[, servo period])."""
    moving = [i for i in range(1, len(rows)) if rows[i][1:4] != rows[i - 1][1:4]]
    if not moving:
        raise RuntimeError("the program did not move")
    if moving[0] < 1 or moving[-1] >= len(rows) - 1:
        raise RuntimeError("samples do not start and end at rest")
    first, last = moving[0] - 1, moving[-1]  # rest before; the sample reaching the end
    if any(rows[i][0] - rows[i - 1][0] != 1 for i in range(1, len(rows))):
        raise RuntimeError("the sampler lost samples (gap in the sample numbers)")
    split = {"rapid": 0, "feed": 0, "other": 0}
    for i in range(first + 1, last + 1):  # each period ending at sample i
        t = rows[i][6] or (rows[i + 1][6] if i + 1 < len(rows) else 0)
        if rows[i][1:4] == rows[i - 1][1:4] and rows[i][4] == 0:
            t = 0  # standing inside the cycle (a dwell, a queue drain)
        split["rapid" if t == TYPE_RAPID else "feed" if t in (TYPE_FEED, TYPE_ARC)
              else "other"] += 1
    # per axis, from the commanded positions: peak speed and acceleration
    peak_v, peak_a = {}, {}
    for k, axis in enumerate("xyz", start=1):
        p = [r[k] for r in rows[first:last + 2]]
        peak_v[axis] = round(max(abs(p[i + 1] - p[i]) for i in range(len(p) - 1)) / period, 3)
        peak_a[axis] = round(max(abs(p[i + 1] - 2 * p[i] + p[i - 1])
                                 for i in range(1, len(p) - 1)) / period ** 2, 1)
    late, missed = late_invocations(rows, first, last)
    return {"cycle_time_s": round((last - first) * period, 6),
            "late_servo_invocations": late, "missed_servo_periods": missed,
            "axis_peak_velocity_mm_s": peak_v, "axis_peak_acceleration_mm_s2": peak_a,
            "feed_time_s": round(split["feed"] * period, 6),
            "rapid_time_s": round(split["rapid"] * period, 6),
            "other_time_s": round(split["other"] * period, 6),
            "periods": last - first, "window": (first, last),
            "peak_velocity_mm_s": max(r[4] for r in rows[first:last + 1])}


def run(program, motion, outdir=None, timeout=300):
    """Run PROGRAM on LinuxCNC configured from MOTION; returns the summary dict."""
    if not installed():
        raise FileNotFoundError("LinuxCNC (linuxcnc, halsampler) is not installed")
    program = os.path.abspath(program)
    period = float(motion["period_s"])
    mdi = ["G64 P%s Q0" % repr(float(motion["blend_tolerance_mm"]))]
    rundir = tempfile.mkdtemp(prefix="bezcam-lcnc.")
    try:
        ini = os.path.join(rundir, "anchor.ini")
        with open(ini, "w") as f:
            f.write(ini_text(motion, os.path.join(HERE, "driver.py"),
                             os.path.join(rundir, "anchor.hal")))
        depth = int(timeout / period) + 1000  # the FIFO can hold the whole run
        with open(os.path.join(rundir, "anchor.hal"), "w") as f:
            f.write(HAL % (min(depth, 2000000), 1.0 / period))
        with open(os.path.join(rundir, "tool.tbl"), "w") as f:
            f.write("".join("T%d P%d D6 Z0\n" % (t, t) for t in range(1, 21)))
        open(os.path.join(rundir, "anchor.var"), "w").close()
        prog = os.path.join(rundir, "program.ngc")
        shutil.copy(program, prog)
        with open(LOCK, "w") as lk:
            fcntl.flock(lk, fcntl.LOCK_EX)  # waits for a run in progress
            others = foreign_linuxcnc()
            if others:
                raise RuntimeError("LinuxCNC processes not started by this run are "
                                   "present (pids %s): refusing to start" % others)
            wall0 = time.monotonic()
            rc = start_and_wait(rundir, ini, prog, mdi, timeout)
            wall = time.monotonic() - wall0
        drv = {}
        if os.path.exists(os.path.join(rundir, "driver.json")):
            with open(os.path.join(rundir, "driver.json")) as f:
                drv = json.load(f)
        if not drv.get("ok"):
            with open(os.path.join(rundir, "linuxcnc.log")) as f:
                tail = f.read()[-3000:]
            raise RuntimeError("LinuxCNC run failed (script status %d): %s\n%s"
                               % (rc, "; ".join(drv.get("errors", ["no driver report"])),
                                  tail))
        p_q = (drv.get("settings") or [None] * 5)[3:5]
        if None in p_q or abs(p_q[0] - float(motion["blend_tolerance_mm"])) > 1e-9 \
                or p_q[1] != 0:
            raise RuntimeError("LinuxCNC's G64 P, Q before the run are %s, not %s"
                               % (p_q, mdi[0]))
        rows = read_samples(os.path.join(rundir, "samples.raw"))
        if drv.get("overruns"):
            raise RuntimeError("sampler FIFO overran %d times" % drv["overruns"])
        end = drv.get("final_position")
        if not rows or end is None or \
                max(abs(rows[-1][1 + i] - end[i]) for i in range(3)) > 1e-5:
            raise RuntimeError("the samples end at %s, LinuxCNC at %s"
                               % (rows[-1][1:4] if rows else None, end))
        res = analyse(rows, period)
        # the motion queue's low-water mark while the machine moved and the
        # program was still being read (a queue that runs low starves the
        # planner's look-ahead)
        moving = [q for _, q, read, line, _, _ in drv.get("polls", []) if line > 0 and read > 0]
        res["queue_low"] = min(moving) if moving else None
        res.update(program=program, period_s=period, mdi=mdi, g64_settings=drv.get("settings"),
                   wall_s=round(wall, 3), linuxcnc_messages=drv.get("messages", []))
        if outdir:
            os.makedirs(outdir, exist_ok=True)
            first, last = res["window"]
            n0 = rows[first][0]
            with open(os.path.join(outdir, "samples.tsv"), "w") as f:
                f.write("# t_s x_mm y_mm z_mm v_mm_s line motion_type\n")
                for r in rows[first:last + 2]:
                    f.write("%.4f\t%.6f\t%.6f\t%.6f\t%.6f\t%d\t%d\n"
                            % ((r[0] - n0) * period, r[1], r[2], r[3], r[4], r[5], r[6]))
            with open(os.path.join(outdir, "summary.json"), "w") as f:
                json.dump(res, f, indent=1)
            shutil.copy(ini, outdir)
        return res
    finally:
        if os.environ.get("LCNC_RUN_KEEP"):
            print("lcnc_run: run directory kept: " + rundir, file=sys.stderr)
        else:
            shutil.rmtree(rundir, ignore_errors=True)


def interrupt_on_sigterm():
    """SIGTERM (ctest, a CI runner) ends a run like Ctrl-C: LinuxCNC is stopped first."""
    def handler(signum, frame):
        raise KeyboardInterrupt("signal %d" % signum)
    signal.signal(signal.SIGTERM, handler)


def main(argv=None):
    interrupt_on_sigterm()
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("program")
    ap.add_argument("--profile", required=True, help="machine profile JSON with 'motion'")
    ap.add_argument("--out", help="write samples.tsv and summary.json here")
    ap.add_argument("--timeout", type=float, default=300, help="seconds for the program")
    a = ap.parse_args(argv)
    try:
        motion = motion_of(a.profile)
    except (Refused, OSError, ValueError) as ex:
        print("lcnc_run: %s" % ex, file=sys.stderr)
        return 2
    try:
        res = run(a.program, motion, a.out, a.timeout)
    except FileNotFoundError as ex:
        print("lcnc_run: %s" % ex, file=sys.stderr)
        return 3
    except RuntimeError as ex:
        print("lcnc_run: %s" % ex, file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("lcnc_run: interrupted; LinuxCNC stopped", file=sys.stderr)
        return 130
    print(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
