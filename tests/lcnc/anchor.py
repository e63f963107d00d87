#!/usr/bin/python3
"""LinuxCNC as the anchor: bezcam's predicted cycle times against LinuxCNC's.

    /usr/bin/python3 tests/lcnc/anchor.py [--bezcam build/bezcam]
        [--profile machines/linuxcnc.json] [--only REGEX] [--results DIR]
        [--lcnc-only]

For every program (the synthetic ones in tests/lcnc/programs/ and the ones
bezcam's `convert` writes at test time from samples/, see PROGRAMS_FROM_BEZCAM)
it runs real LinuxCNC 2.9 configured from the profile's `motion` object
(lcnc_run.py) and `bezcam simulate --program P --machine PROFILE --report R`,
prints a table (program, LinuxCNC s, bezcam s, ratio) and how many agree
within 2 %, and fails if any is off by more than 5 %.

Exit status: 0 all within 5 %, 1 a program off by more or a run failed,
2 usage or a profile without `motion`, 77 LinuxCNC is not installed (ctest
counts that as skipped). --lcnc-only runs the LinuxCNC side alone;
--results DIR keeps each LinuxCNC run's samples (DIR/<program>/) and writes
DIR/summary.tsv.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # nothing written into the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import lcnc_run  # noqa: E402

TOLERANCE = 0.05   # fail above
GOOD = 0.02        # counted as agreeing closely
SKIP = 77

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


def synthetic_programs(only):
    d = os.path.join(HERE, "programs")
    return [(f[:-4], os.path.join(d, f)) for f in sorted(os.listdir(d))
            if f.endswith(".ngc") and (not only or re.search(only, f[:-4]))]


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
    ap.add_argument("--bezcam", default=os.path.join(ROOT, "build", "bezcam"))
    ap.add_argument("--profile", default=os.path.join(ROOT, "machines", "linuxcnc.json"),
                    help="machine profile with a 'motion' object (also given to bezcam)")
    ap.add_argument("--only", help="run only the programs whose name matches this regex")
    ap.add_argument("--results", help="keep LinuxCNC's samples in DIR/<program>/ and "
                    "write DIR/summary.tsv")
    ap.add_argument("--lcnc-only", action="store_true", help="run the LinuxCNC side alone")
    a = ap.parse_args(argv)

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
    if not os.access(a.bezcam, os.X_OK):
        print("anchor: no bezcam executable at %s (build the bezcam target)" % a.bezcam)
        return 2
    profile = os.path.abspath(a.profile)

    rows, failures = [], []
    t_start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="bezcam-anchor.") as tmp:
        try:
            progs = synthetic_programs(a.only) + bezcam_programs(a.bezcam, profile, tmp, a.only)
        except RuntimeError as ex:
            print("anchor: %s" % ex)
            return 1
        if not progs:
            print("anchor: no program matches %r" % a.only)
            return 2
        print("%-28s %10s %10s %7s" % ("program", "LinuxCNC s", "bezcam s", "ratio"))
        for name, path in progs:
            outdir = os.path.join(a.results, name) if a.results else None
            row = {"program": name}
            try:
                res = lcnc_run.run(path, motion, outdir)
                row.update(lcnc=res["cycle_time_s"], feed=res["feed_time_s"],
                           rapid=res["rapid_time_s"], other=res["other_time_s"])
                if name == "limits-g61":
                    share = check_limits(res, motion)
                    row["note"] = ("LinuxCNC at the profile's axis speeds; peak acceleration "
                                   "%s of the axis limits" % "/".join(
                                       "%.2f" % share[k] for k in "xyz"))
                if outdir:
                    with open(path) as src, open(os.path.join(outdir, "program.ngc"), "w") as dst:
                        dst.write(src.read())
                if not a.lcnc_only:
                    row["bezcam"] = bezcam_cycle(a.bezcam, path, profile, tmp)
                    row["ratio"] = row["bezcam"] / row["lcnc"]
            except (RuntimeError, FileNotFoundError, KeyError, ValueError) as ex:
                row["error"] = str(ex).splitlines()[0]
                failures.append("%s: %s" % (name, ex))
            rows.append(row)
            print("%-28s %10s %10s %7s%s" % (
                name, "%.3f" % row["lcnc"] if "lcnc" in row else "-",
                "%.3f" % row["bezcam"] if "bezcam" in row else "-",
                "%.3f" % row["ratio"] if "ratio" in row else "-",
                "   " + row["error"] if "error" in row else
                ("   OFF BY MORE THAN 5 %" if "ratio" in row and
                 abs(row["ratio"] - 1) > TOLERANCE else
                 "   (%s)" % row["note"] if "note" in row else "")), flush=True)

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
    print("%d programs, LinuxCNC time %.1f s (wall %.0f s)" % (
        len(rows), sum(r.get("lcnc", 0) for r in rows), time.monotonic() - t_start))
    if not a.lcnc_only:
        print("%d of %d within 2 %%, %d off by more than 5 %%"
              % (len(close), len(compared), len(off)))
    for fl in failures:
        print("FAILED " + fl)
    return 1 if failures or off else 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt:
        print("anchor: interrupted; LinuxCNC stopped")
        sys.exit(130)
