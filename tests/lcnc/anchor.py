#!/usr/bin/python3
"""LinuxCNC as the anchor: bezcam's predicted cycle times against LinuxCNC's.

    /usr/bin/python3 tests/lcnc/anchor.py --check [--bezcam build/bezcam]
        [--profile machines/linuxcnc.json] [--only REGEX]
    /usr/bin/python3 tests/lcnc/anchor.py [--bezcam build/bezcam]
        [--profile machines/linuxcnc.json] [--only REGEX] [--results DIR]
        [--lcnc-only] [--update]

The programs are the synthetic ones in tests/lcnc/programs/ and bezcam's
own output in tests/lcnc/programs/bz/ (written by `convert` from samples/,
see PROGRAMS_FROM_BEZCAM). LinuxCNC's cycle time for each is kept, reviewed,
in tests/lcnc/reference.tsv with the program's fingerprint, the LinuxCNC
version and the profile's motion object it was measured for.

--check (ctest LinuxCNC.CycleTimeReference; no LinuxCNC needed, seconds):
runs `bezcam simulate --program P --machine PROFILE --report R` on every
program and compares with reference.tsv; fails if any is off by more than
3 %, or if the reference does not hold the program as it is (its
fingerprint) or the profile's motion object as it is.

Without --check (the live anchor, minutes; the build target
linuxcnc_anchor): runs real LinuxCNC 2.9 configured from the profile's
`motion` object (lcnc_run.py) on every program, writing bezcam's programs
afresh from samples/. A program runs until two runs agree within 3 servo
periods (at most 4 runs): a run LinuxCNC's task fed too slowly (a busy
machine) is slower and does not repeat. Each run's late servo invocations
and the motion queue's low-water mark are shown. It prints a table
(program, LinuxCNC s, runs, reference s, bezcam s, ratio), fails if bezcam
is off by more than 3 %, and reports where LinuxCNC's time or a program
differs from reference.tsv; --update rewrites reference.tsv and the
programs in programs/bz/ from this run instead.

Exit status: 0 all within 3 % (and, live, the reference reproduced or
updated), 1 a program off by more, a run failed or did not reproduce, or
the reference differs, 2 usage or a profile without `motion`, 77 LinuxCNC
is not installed (live; ctest counts that as skipped). --lcnc-only runs the
LinuxCNC side alone; --results DIR keeps each LinuxCNC run's samples
(DIR/<program>/) and writes DIR/summary.tsv.
"""
import argparse
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # nothing written into the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import lcnc_run  # noqa: E402

TOLERANCE = 0.03   # fail above
GOOD = 0.02        # counted as agreeing closely
SKIP = 77
REFERENCE = os.path.join(HERE, "reference.tsv")
PROGRAMS = os.path.join(HERE, "programs")  # bezcam's in PROGRAMS/bz/
AGREE_PERIODS = 3  # two undisturbed runs of a program agree to this (servo periods)
MAX_RUNS = 4       # runs of one program at most

# (name, sample, output mode, feed in mm/min or None for the job's own)
PROGRAMS_FROM_BEZCAM = [
    ("bz-semicircle-lines", "curve-semicircle.json", "lines", None),
    ("bz-semicircle-arcs", "curve-semicircle.json", "arcs", None),
    ("bz-semicircle-nurbs", "curve-semicircle.json", "nurbs", None),
    ("bz-teardrop-lines-F4000", "path-closed-teardrop.json", "lines", 4000),
    ("bz-teardrop-arcs-F4000", "path-closed-teardrop.json", "arcs", 4000),
    ("bz-teardrop-nurbs-F4000", "path-closed-teardrop.json", "nurbs", 4000),
    ("bz-wave-lines-F6000", "curve-bspline-wave.json", "lines", 6000),
    ("bz-wave-arcs-F6000", "curve-bspline-wave.json", "arcs", 6000),
    ("bz-wave-nurbs-F6000", "curve-bspline-wave.json", "nurbs", 6000),
    ("bz-hermite-lines-F6000", "curve-interpolate-hermite.json", "lines", 6000),
    ("bz-hermite-arcs-F6000", "curve-interpolate-hermite.json", "arcs", 6000),
    ("bz-hermite-nurbs-F6000", "curve-interpolate-hermite.json", "nurbs", 6000),
    ("bz-circle-lines-F6000", "curve-nurbs-circle.json", "lines", 6000),
    ("bz-circle-arcs-F6000", "curve-nurbs-circle.json", "arcs", 6000),
    ("bz-circle-nurbs-F6000", "curve-nurbs-circle.json", "nurbs", 6000),
    ("bz-quarter-lines-F6000", "curve-rational-quarter-circle.json", "lines", 6000),
    ("bz-quarter-arcs-F6000", "curve-rational-quarter-circle.json", "arcs", 6000),
    ("bz-quarter-nurbs-F6000", "curve-rational-quarter-circle.json", "nurbs", 6000),
    ("bz-finish-lines-F6000", "job-finish-pass.json", "lines", 6000),
    ("bz-finish-arcs-F6000", "job-finish-pass.json", "arcs", 6000),
    ("bz-finish-nurbs-F6000", "job-finish-pass.json", "nurbs", 6000),
]


def with_feed(job, feed, tmp):
    """A copy of the job whose every feed is FEED (the sample's other settings kept)."""
    with open(job) as f:
        data = json.load(f)

    def walk(node):
        if isinstance(node, dict):
            for k, v in node.items():
                if k == "feed" and isinstance(v, (int, float)):
                    node[k] = feed
                else:
                    walk(v)
        elif isinstance(node, list):
            for v in node:
                walk(v)
    walk(data)
    out = os.path.join(tmp, "F%d-%s" % (feed, os.path.basename(job)))
    with open(out, "w") as f:
        json.dump(data, f)
    return out


def bezcam_programs(bezcam, profile, tmp, only):
    with open(profile) as f:
        preamble = json.load(f).get("preamble", [])
    progs = []
    for name, sample, mode, feed in PROGRAMS_FROM_BEZCAM:
        if only and not re.search(only, name):
            continue
        job = os.path.join(ROOT, "samples", sample)
        if feed is not None:
            job = with_feed(job, feed, tmp)
        out = os.path.join(tmp, name + ".ngc")
        # bezcam's simulator starts at an unknown position and times no move out of
        # it; LinuxCNC starts at X0 Y0 Z0: the profile's preamble plus G0 X0 Y0 Z0
        # starts both there
        r = subprocess.run([bezcam, "convert", job, "--machine", profile, "--output", mode,
                            "--preamble", "\\n".join(preamble + ["G0 X0 Y0 Z0"]),
                            "-o", out, "-q"], capture_output=True, text=True)
        if r.returncode != 0:
            raise RuntimeError("bezcam convert %s --output %s failed: %s"
                               % (sample, mode, r.stderr.strip()))
        if feed is not None and not re.search(r"F%d\b" % feed, open(out).read()):
            raise RuntimeError("%s: the program has no F%d (the feed did not reach it)"
                               % (name, feed))
        progs.append((name, out))
    return progs


def programs_in(d, only):
    if not os.path.isdir(d):
        return []
    return [(f[:-4], os.path.join(d, f)) for f in sorted(os.listdir(d))
            if f.endswith(".ngc") and (not only or re.search(only, f[:-4]))]


def synthetic_programs(only, d=PROGRAMS):
    return programs_in(d, only)


def fingerprint(data):
    """The first 16 hex digits of the SHA-256 of bytes or of a JSON value."""
    if not isinstance(data, bytes):
        data = json.dumps(data, sort_keys=True).encode()
    return hashlib.sha256(data).hexdigest()[:16]


def program_fingerprint(path):
    with open(path, "rb") as f:
        return fingerprint(f.read())


def linuxcnc_version():
    r = subprocess.run(["dpkg-query", "-W", "-f", "${Version}", "linuxcnc-uspace"],
                       capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 and r.stdout.strip() else "unknown"


REFERENCE_COLUMNS = ("program", "program_sha256", "cycle_time_s", "feed_time_s",
                     "rapid_time_s", "other_time_s")


def read_reference(path):
    """(LinuxCNC version, motion fingerprint, {program: row}) of reference.tsv."""
    meta, rows = {}, {}
    with open(path) as f:
        lines = f.read().splitlines()
    body = []
    for ln in lines:
        if ln.startswith("#"):
            for key in ("linuxcnc-uspace", "motion"):
                m = re.search(r"\b%s (\S+)" % key, ln)
                if m:
                    meta[key] = m.group(1).rstrip(",;")
        elif ln.strip():
            body.append(ln.split("\t"))
    if not body or tuple(body[0]) != REFERENCE_COLUMNS:
        raise ValueError("%s: expected the columns %s" % (path, " ".join(REFERENCE_COLUMNS)))
    for cells in body[1:]:
        if len(cells) != len(REFERENCE_COLUMNS):
            raise ValueError("%s: a row with %d cells: %s" % (path, len(cells), cells))
        row = dict(zip(REFERENCE_COLUMNS, cells))
        for k in REFERENCE_COLUMNS[2:]:
            row[k] = float(row[k])
        rows[row["program"]] = row
    if "motion" not in meta:
        raise ValueError("%s: the header does not name the motion object it was measured for" % path)
    return meta.get("linuxcnc-uspace", "unknown"), meta["motion"], rows


def write_reference(path, version, motion_fp, rows):
    with open(path, "w") as f:
        f.write("# LinuxCNC's cycle times for the anchor's programs, measured by\n"
                "# tests/lcnc/anchor.py --update (docs/linuxcnc-anchor.md) on\n"
                "# linuxcnc-uspace %s, machines/linuxcnc.json motion %s\n"
                "# (fingerprints: the first 16 hex digits of SHA-256; each time is the\n"
                "# faster of two runs that agreed within %d servo periods)\n"
                % (version, motion_fp, AGREE_PERIODS))
        f.write("\t".join(REFERENCE_COLUMNS) + "\n")
        for name in sorted(rows):
            r = rows[name]
            f.write("%s\t%s\t%.3f\t%.3f\t%.3f\t%.3f\n" % (
                name, r["program_sha256"], r["cycle_time_s"], r["feed_time_s"],
                r["rapid_time_s"], r["other_time_s"]))


def measure(run_once):
    """LinuxCNC's time for one program: runs it until two runs agree within
    AGREE_PERIODS servo periods, at most MAX_RUNS times. Anything that
    disturbs a run (LinuxCNC's task feeding the motion queue too slowly on a
    busy machine) makes it slower, and differently so each time; two runs
    that agree were not disturbed, and the faster is kept. Returns (the run
    kept or None, every run)."""
    runs = []
    while len(runs) < MAX_RUNS:
        runs.append(run_once())
        best = None
        for i in range(len(runs)):
            for j in range(i + 1, len(runs)):
                a, b = runs[i], runs[j]
                if abs(a["periods"] - b["periods"]) <= AGREE_PERIODS:
                    faster = a if a["periods"] <= b["periods"] else b
                    if best is None or faster["periods"] < best["periods"]:
                        best = faster
        if best is not None:
            return best, runs
    return None, runs


def check_limits(res, motion):
    """limits-g61 moves each axis alone, long enough to reach its top speed:
    LinuxCNC must reach exactly the profile's axis velocities, and accelerate
    within the axis limits, at the same share of each (LinuxCNC's planner
    uses a fixed fraction of the limit, 0.9 in exact stop). Otherwise the
    harness did not configure the machine from the profile."""
    bad, share = [], {}
    for axis in "xyz":
        vmax = motion["max_velocity_mm_min"][axis] / 60.0
        amax = float(motion["max_acceleration_mm_s2"][axis])
        v = res["axis_peak_velocity_mm_s"][axis]
        acc = res["axis_peak_acceleration_mm_s2"][axis]
        share[axis] = acc / amax
        if abs(v - vmax) > 0.002 * vmax:
            bad.append("%s peak %.3f mm/s, the profile's limit %.3f" % (axis, v, vmax))
        if not 0.45 * amax <= acc <= 1.01 * amax:
            bad.append("%s peak acceleration %.1f mm/s2, the profile's limit %.1f"
                       % (axis, acc, amax))
    if max(share.values()) - min(share.values()) > 0.06:
        bad.append("the axes use different shares of their acceleration limits: %s" % share)
    if bad:
        raise RuntimeError("limits-g61: the harness did not configure LinuxCNC's "
                           "limits from the profile: " + "; ".join(bad))
    return share


def check(a, profile, motion):
    """--check: bezcam against the reference, no LinuxCNC."""
    try:
        version, motion_fp, ref = read_reference(a.reference)
    except (OSError, ValueError) as ex:
        print("anchor: %s" % ex)
        return 1
    if motion_fp != fingerprint(motion):
        print("anchor: %s was measured for another motion object (fingerprint %s, %s's is %s): "
              "run the live anchor with --update (docs/linuxcnc-anchor.md)"
              % (a.reference, motion_fp, a.profile, fingerprint(motion)))
        return 1
    progs = synthetic_programs(a.only, a.programs) + programs_in(os.path.join(a.programs, "bz"), a.only)
    if not progs:
        print("anchor: no program matches %r" % a.only)
        return 2
    names = set(n for n, _ in progs)
    failures = ["%s: in the reference, no such program" % n for n in sorted(ref)
                if n not in names and (not a.only or re.search(a.only, n))]
    rows = []
    t_start = time.monotonic()
    print("LinuxCNC's times from %s (linuxcnc-uspace %s)" % (os.path.relpath(a.reference, ROOT), version))
    print("%-28s %10s %10s %7s" % ("program", "LinuxCNC s", "bezcam s", "ratio"))
    with tempfile.TemporaryDirectory(prefix="bezcam-anchor.") as tmp:
        for name, path in progs:
            row = {"program": name}
            r = ref.get(name)
            try:
                if r is None:
                    raise RuntimeError("no LinuxCNC time in the reference: run the live anchor "
                                       "with --update")
                if r["program_sha256"] != program_fingerprint(path):
                    raise RuntimeError("the program is not the one LinuxCNC timed (fingerprint %s, "
                                       "the reference's %s): run the live anchor with --update"
                                       % (program_fingerprint(path), r["program_sha256"]))
                row["lcnc"] = r["cycle_time_s"]
                row["bezcam"] = bezcam_cycle(a.bezcam, path, profile, tmp)
                row["ratio"] = row["bezcam"] / row["lcnc"]
            except RuntimeError as ex:
                row["error"] = str(ex).splitlines()[0]
                failures.append("%s: %s" % (name, ex))
            rows.append(row)
            print("%-28s %10s %10s %7s%s" % (
                name, "%.3f" % row["lcnc"] if "lcnc" in row else "-",
                "%.3f" % row["bezcam"] if "bezcam" in row else "-",
                "%.3f" % row["ratio"] if "ratio" in row else "-",
                "   " + row["error"] if "error" in row else
                "   OFF BY MORE THAN 3 %" if abs(row["ratio"] - 1) > TOLERANCE else ""), flush=True)
    compared = [r for r in rows if "ratio" in r]
    off = [r for r in compared if abs(r["ratio"] - 1) > TOLERANCE]
    close = [r for r in compared if abs(r["ratio"] - 1) <= GOOD]
    print("%d programs, %d of %d within 2 %%, %d off by more than 3 %% (%.1f s)"
          % (len(rows), len(close), len(compared), len(off), time.monotonic() - t_start))
    for fl in failures:
        print("FAILED " + fl)
    return 1 if failures or off else 0


def bezcam_cycle(bezcam, program, profile, tmp):
    report = os.path.join(tmp, os.path.basename(program) + ".report.json")
    r = subprocess.run([bezcam, "simulate", "--program", program, "--machine", profile,
                        "--report", report, "-q"], capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError("bezcam simulate failed (%d): %s" % (r.returncode, r.stderr.strip()))
    with open(report) as f:
        return float(json.load(f)["cycle_time_s"])


def main(argv=None):
    lcnc_run.interrupt_on_sigterm()
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true",
                    help="compare bezcam with LinuxCNC's times in the reference (no LinuxCNC run)")
    ap.add_argument("--bezcam", default=os.path.join(ROOT, "build", "bezcam"))
    ap.add_argument("--profile", default=os.path.join(ROOT, "machines", "linuxcnc.json"),
                    help="machine profile with a 'motion' object (also given to bezcam)")
    ap.add_argument("--reference", default=REFERENCE, help="LinuxCNC's times (reference.tsv)")
    ap.add_argument("--programs", default=PROGRAMS,
                    help="the synthetic programs, bezcam's in its bz/ folder (tests/lcnc/programs)")
    ap.add_argument("--only", help="run only the programs whose name matches this regex")
    ap.add_argument("--results", help="keep LinuxCNC's samples in DIR/<program>/ and "
                    "write DIR/summary.tsv")
    ap.add_argument("--lcnc-only", action="store_true", help="run the LinuxCNC side alone")
    ap.add_argument("--update", action="store_true",
                    help="write this run's times into the reference and bezcam's programs into "
                    "programs/bz/")
    a = ap.parse_args(argv)
    if a.check and (a.update or a.lcnc_only or a.results):
        print("anchor: --check runs no LinuxCNC: --update, --lcnc-only and --results are for "
              "the live anchor")
        return 2

    if not a.check:
        if not lcnc_run.installed():
            print("anchor: LinuxCNC (linuxcnc, halsampler) is not installed: skipped")
            return SKIP
        try:
            import linuxcnc  # noqa: F401  (the driver needs it; Debian's python3 has it)
        except ImportError:
            print("anchor: %s has no 'linuxcnc' module: skipped" % sys.executable)
            return SKIP
    try:
        motion = lcnc_run.motion_of(a.profile)
    except (lcnc_run.Refused, OSError, ValueError) as ex:
        print("anchor: %s" % ex)
        return 2
    if not os.access(a.bezcam, os.X_OK) and not a.lcnc_only:
        print("anchor: no bezcam executable at %s (build the bezcam target)" % a.bezcam)
        return 2
    profile = os.path.abspath(a.profile)
    if a.check:
        return check(a, profile, motion)
    period = float(motion["period_s"])

    try:
        _, ref_motion, ref = read_reference(a.reference)
    except (OSError, ValueError) as ex:
        print("anchor: no reference to compare with (%s)" % ex)
        ref_motion, ref = None, {}
    if ref and ref_motion != fingerprint(motion):
        print("anchor: %s was measured for another motion object: its times are not compared"
              % a.reference)
        ref = {}

    rows, failures, ref_diffs = [], [], []
    t_start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="bezcam-anchor.") as tmp:
        try:
            progs = synthetic_programs(a.only, a.programs) + bezcam_programs(a.bezcam, profile, tmp, a.only)
        except RuntimeError as ex:
            print("anchor: %s" % ex)
            return 1
        if not progs:
            print("anchor: no program matches %r" % a.only)
            return 2
        print("%-28s %10s %4s %10s %10s %7s" % ("program", "LinuxCNC s", "runs", "ref s",
                                               "bezcam s", "ratio"))
        for name, path in progs:
            outdir = os.path.join(a.results, name) if a.results else None
            row = {"program": name, "path": path, "sha": program_fingerprint(path)}
            notes = []
            try:
                count = [0]

                def run_once():
                    count[0] += 1
                    return lcnc_run.run(path, motion,
                                        os.path.join(outdir, "run-%d" % count[0]) if outdir else None)
                res, runs = measure(run_once)
                row["runs"] = len(runs)
                if res is None:
                    raise RuntimeError("LinuxCNC's time did not reproduce in %d runs (%s periods): "
                                       "the machine is too busy for the live anchor"
                                       % (len(runs), ", ".join(str(r["periods"]) for r in runs)))
                row.update(lcnc=res["cycle_time_s"], feed=res["feed_time_s"],
                           rapid=res["rapid_time_s"], other=res["other_time_s"])
                slow = [r for r in runs if r["periods"] > res["periods"] + AGREE_PERIODS]
                if slow:
                    notes.append("%d disturbed run%s: %s; the run kept: queue low %s" % (
                        len(slow), "" if len(slow) == 1 else "s",
                        ", ".join("+%d periods, queue low %s" % (r["periods"] - res["periods"],
                                                                 r.get("queue_low"))
                                  for r in slow), res.get("queue_low")))
                if res.get("missed_servo_periods"):
                    notes.append("%d servo periods missed" % res["missed_servo_periods"])
                if name == "limits-g61":
                    share = check_limits(res, motion)
                    notes.append("LinuxCNC at the profile's axis speeds; peak acceleration "
                                 "%s of the axis limits" % "/".join("%.2f" % share[k] for k in "xyz"))
                if outdir:
                    os.makedirs(outdir, exist_ok=True)
                    with open(path) as src, open(os.path.join(outdir, "program.ngc"), "w") as dst:
                        dst.write(src.read())
                # against the reference: the same program must take the same time
                r = ref.get(name)
                stored = os.path.join(a.programs, "bz", name + ".ngc")
                if name.startswith("bz-") and (not os.path.exists(stored)
                                               or program_fingerprint(stored) != row["sha"]):
                    ref_diffs.append("%s: convert writes another program than programs/bz/%s.ngc"
                                     % (name, name))
                    notes.append("program changed")
                elif r is None:
                    ref_diffs.append("%s: not in the reference" % name)
                    notes.append("not in the reference")
                elif r["program_sha256"] != row["sha"]:
                    ref_diffs.append("%s: the program is not the one in the reference" % name)
                    notes.append("program changed")
                else:
                    row["ref"] = r["cycle_time_s"]
                    d = res["periods"] - int(round(r["cycle_time_s"] / period))
                    if abs(d) > AGREE_PERIODS:
                        ref_diffs.append("%s: %.3f s, the reference %.3f s (%+d periods)"
                                         % (name, res["cycle_time_s"], r["cycle_time_s"], d))
                        notes.append("differs from the reference")
                if not a.lcnc_only:
                    row["bezcam"] = bezcam_cycle(a.bezcam, path, profile, tmp)
                    row["ratio"] = row["bezcam"] / row["lcnc"]
                    if abs(row["ratio"] - 1) > TOLERANCE:
                        notes.insert(0, "OFF BY MORE THAN 3 %")
            except (RuntimeError, FileNotFoundError, KeyError, ValueError) as ex:
                row["error"] = str(ex).splitlines()[0]
                failures.append("%s: %s" % (name, ex))
            rows.append(row)
            print("%-28s %10s %4s %10s %10s %7s%s" % (
                name, "%.3f" % row["lcnc"] if "lcnc" in row else "-", row.get("runs", "-"),
                "%.3f" % row["ref"] if "ref" in row else "-",
                "%.3f" % row["bezcam"] if "bezcam" in row else "-",
                "%.3f" % row["ratio"] if "ratio" in row else "-",
                "   " + row["error"] if "error" in row else
                "   (%s)" % "; ".join(notes) if notes else ""), flush=True)

        if a.update:
            measured = {r["program"]: r for r in rows if "lcnc" in r}
            if failures:
                print("anchor: the reference was not updated: %d program%s failed"
                      % (len(failures), "" if len(failures) == 1 else "s"))
            else:
                keep = {n: v for n, v in ref.items() if n not in measured and
                        (a.only and not re.search(a.only, n))}
                for n, r in measured.items():
                    keep[n] = {"program_sha256": r["sha"], "cycle_time_s": r["lcnc"],
                               "feed_time_s": r["feed"], "rapid_time_s": r["rapid"],
                               "other_time_s": r["other"]}
                    if n.startswith("bz-"):
                        os.makedirs(os.path.join(a.programs, "bz"), exist_ok=True)
                        shutil.copy(r["path"], os.path.join(a.programs, "bz", n + ".ngc"))
                write_reference(a.reference, linuxcnc_version(), fingerprint(motion), keep)
                print("anchor: wrote %s (%d programs)" % (a.reference, len(keep)))
                ref_diffs = []

    if a.results:
        os.makedirs(a.results, exist_ok=True)
        # rows of programs not run this time (--only) are kept
        table = os.path.join(a.results, "summary.tsv")
        lines = {}
        if os.path.exists(table):
            with open(table) as f:
                lines = {ln.split("\t", 1)[0]: ln for ln in f.read().splitlines()[1:] if ln}
        for r in rows:
            if "lcnc" in r:
                lines[r["program"]] = "%s\t%.3f\t%.3f\t%.3f\t%.3f\t%s\t%s" % (
                    r["program"], r["lcnc"], r["feed"], r["rapid"], r["other"],
                    "%.3f" % r["bezcam"] if "bezcam" in r else "-",
                    "%.3f" % r["ratio"] if "ratio" in r else "-")
        with open(table, "w") as f:
            f.write("program\tcycle_time_s\tfeed_time_s\trapid_time_s\tother_time_s"
                    "\tbezcam_cycle_time_s\tratio\n")
            f.write("".join(lines[k] + "\n" for k in sorted(lines)))
    compared = [r for r in rows if "ratio" in r]
    off = [r for r in compared if abs(r["ratio"] - 1) > TOLERANCE]
    close = [r for r in compared if abs(r["ratio"] - 1) <= GOOD]
    print("%d programs, %d LinuxCNC runs, LinuxCNC time %.1f s (wall %.0f s)" % (
        len(rows), sum(r.get("runs", 0) for r in rows), sum(r.get("lcnc", 0) for r in rows),
        time.monotonic() - t_start))
    if not a.lcnc_only:
        print("%d of %d within 2 %%, %d off by more than 3 %%"
              % (len(close), len(compared), len(off)))
    for d in ref_diffs:
        print("REFERENCE " + d)
    if ref_diffs:
        print("anchor: LinuxCNC's times or the programs differ from %s: review, then rerun "
              "with --update" % os.path.relpath(a.reference, ROOT))
    for fl in failures:
        print("FAILED " + fl)
    return 1 if failures or off or ref_diffs else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt:
        print("anchor: interrupted; LinuxCNC stopped")
        sys.exit(130)
