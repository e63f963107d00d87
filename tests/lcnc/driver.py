#!/usr/bin/python3
"""Headless operator for one LinuxCNC run (bezcam's LinuxCNC anchor).

lcnc_run.py names this script as [DISPLAY]DISPLAY in the INI it writes, so
the `linuxcnc` start script runs it in the foreground once task, io and HAL
are up, and shuts LinuxCNC down when it exits. It acts like a GUI through
the `linuxcnc` Python module: estop reset, machine on, home in place, the
MDI lines given, AUTO, open the program, run it, wait until it is done.
Around the run it gates the HAL `sampler` (one row per servo period) whose
FIFO `halsampler` copies to a file.

Every wait polls LinuxCNC's own status (NML stat, HAL pins) against a
deadline: nothing waits a fixed time hoping a state has been reached.

Input, from the environment: LCNC_RUN_DIR (writes driver.json and
samples.raw there), LCNC_RUN_PROGRAM, LCNC_RUN_MDI (';'-separated lines),
LCNC_RUN_TIMEOUT (seconds for the program). Exit status 0 if the program
ran to its end with no error.
"""
import json
import os
import subprocess
import sys
import time

import linuxcnc

RUN_DIR = os.environ["LCNC_RUN_DIR"]
PROGRAM = os.environ["LCNC_RUN_PROGRAM"]
MDI = [m.strip() for m in os.environ.get("LCNC_RUN_MDI", "").split(";") if m.strip()]
TIMEOUT = float(os.environ.get("LCNC_RUN_TIMEOUT", "300"))
POLL = 0.002      # seconds between two looks at the status
TAIL_SAMPLES = 20  # rest samples recorded after the program's end

report = {"ok": False, "errors": [], "messages": [], "log": []}
t0 = time.monotonic()
stat = linuxcnc.stat()
cmd = linuxcnc.command()
errs = linuxcnc.error_channel()


def note(text):
    report["log"].append("%.3f %s" % (time.monotonic() - t0, text))


def take_errors():
    """Empty the NML error channel; True if it held an error."""
    bad = False
    while True:
        m = errs.poll()
        if not m:
            return bad
        kind, text = m
        if kind in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR):
            report["errors"].append(text)
            bad = True
        else:
            report["messages"].append(text)


def until(cond, seconds, what):
    """Poll until cond() holds; errors on the channel or the deadline abort."""
    end = time.monotonic() + seconds
    while True:
        stat.poll()
        if cond():
            return
        if take_errors():
            raise RuntimeError("LinuxCNC error while waiting for " + what)
        if time.monotonic() > end:
            raise RuntimeError("no %s within %.0f s" % (what, seconds))
        time.sleep(POLL)


def hal_get(name):
    out = subprocess.run(["halcmd", "getp", name], capture_output=True, text=True, check=True)
    return out.stdout.strip()


def hal_set(name, value):
    subprocess.run(["halcmd", "setp", name, str(value)], capture_output=True, check=True)


def task_up():
    try:
        stat.poll()
    except linuxcnc.error:
        return False
    return stat.task_state in (linuxcnc.STATE_ESTOP, linuxcnc.STATE_ESTOP_RESET,
                               linuxcnc.STATE_OFF, linuxcnc.STATE_ON)


def set_mode(mode, what):
    cmd.mode(mode)
    until(lambda: stat.task_mode == mode, 10, what)


def finished():
    return (stat.interp_state == linuxcnc.INTERP_IDLE and stat.queue == 0
            and stat.exec_state == linuxcnc.EXEC_DONE and stat.inpos
            and stat.state == linuxcnc.RCS_DONE)


def run():
    end = time.monotonic() + 60
    while not task_up():
        if time.monotonic() > end:
            raise RuntimeError("task did not answer within 60 s")
        time.sleep(POLL)
    take_errors()
    cmd.state(linuxcnc.STATE_ESTOP_RESET)
    until(lambda: stat.task_state == linuxcnc.STATE_ESTOP_RESET, 10, "estop reset")
    cmd.state(linuxcnc.STATE_ON)
    until(lambda: stat.task_state == linuxcnc.STATE_ON, 10, "machine on")
    set_mode(linuxcnc.MODE_MANUAL, "manual mode")
    cmd.teleop_enable(0)
    cmd.home(-1)  # HOME_SEARCH_VEL = 0: every joint homes where it is (0)
    until(lambda: all(stat.homed[j] for j in range(stat.joints)), 20, "homing")
    note("homed")
    if MDI:
        set_mode(linuxcnc.MODE_MDI, "MDI mode")
        for line in MDI:
            cmd.mdi(line)
            cmd.wait_complete(10)
            until(lambda: stat.interp_state == linuxcnc.INTERP_IDLE, 10, "MDI " + line)
            note("MDI " + line)
    set_mode(linuxcnc.MODE_AUTO, "auto mode")
    cmd.program_open(PROGRAM)
    cmd.wait_complete(10)
    if take_errors():
        raise RuntimeError("LinuxCNC refused the program")
    stat.poll()
    report["settings"] = list(stat.settings)  # [seq, F, S, G64 P, G64 Q]

    raw = open(os.path.join(RUN_DIR, "samples.raw"), "w")
    sampler = subprocess.Popen(["halsampler", "-t", "-c", "0"], stdout=raw,
                               stderr=subprocess.STDOUT)
    try:
        hal_set("sampler.0.enable", 1)
        cmd.auto(linuxcnc.AUTO_RUN, 0)
        until(lambda: not finished(), 10, "program start")
        note("running")
        # the motion queue and the interpreter at every look (for starvation)
        polls = report["polls"] = []
        end = time.monotonic() + TIMEOUT
        while True:
            stat.poll()
            polls.append([round(time.monotonic() - t0, 4), stat.queue, stat.read_line,
                          stat.motion_line, stat.interp_state, int(stat.queue_full)])
            if finished():
                break
            if take_errors():
                raise RuntimeError("LinuxCNC error while waiting for program end")
            if time.monotonic() > end:
                raise RuntimeError("no program end within %.0f s" % TIMEOUT)
            time.sleep(POLL)
        note("finished")
        report["final_position"] = list(stat.actual_position[:3])
        # a few samples at rest after the end, counted on the servo thread's
        # period counter (integ.0.out, see the HAL file)
        last = float(hal_get("integ.0.out"))
        end = time.monotonic() + 10
        while float(hal_get("integ.0.out")) - last < TAIL_SAMPLES:
            if time.monotonic() > end:
                raise RuntimeError("the servo thread stopped counting periods")
            time.sleep(POLL)
    finally:
        hal_set("sampler.0.enable", 0)
        # halsampler has read everything once the FIFO is empty; SIGTERM makes it
        # flush its output and exit
        end = time.monotonic() + 30
        while int(hal_get("sampler.0.curr-depth")) != 0 and time.monotonic() < end:
            time.sleep(POLL)
        report["overruns"] = int(hal_get("sampler.0.overruns"))
        sampler.terminate()
        try:
            sampler.wait(10)
        except subprocess.TimeoutExpired:
            sampler.kill()
            sampler.wait()
        raw.close()
    report["ok"] = not report["errors"]


def main():
    rc = 1
    try:
        run()
        rc = 0 if report["ok"] else 1
    except Exception as ex:  # recorded; LinuxCNC shuts down when we exit
        report["errors"].append("%s: %s" % (type(ex).__name__, ex))
    finally:
        try:
            cmd.state(linuxcnc.STATE_ESTOP)
        except Exception:
            pass
        with open(os.path.join(RUN_DIR, "driver.json"), "w") as f:
            json.dump(report, f, indent=1)
    return rc


if __name__ == "__main__":
    sys.exit(main())
