#!/usr/bin/env python3
"""Cut every closed contour of real drawings as a part, and count what happens.

Each closed contour of each drawing becomes a job of its own (one entity)
and is converted by the `bezcam` program with `side` outside and inside,
several tool diameters, `tolerance_side` both and waste, and the output
modes asked. Every run must end with exit 0 (cut; "material is left"
warnings allowed) or exit 2 with a refusal whose id is `job.cut` (a tool
that fits nowhere) or `program.travel` (a drawing larger than the
machine); an internal error (exit 70) or anything else fails the sweep,
and its job is saved under --found for a bug report.

The programs written are read back (G-code words, no bezcam code) and two
kinds of wasted block are counted: moves shorter than the rounding unit
(1e-decimals) and moves that double back (a turn of more than
--reverse-deg degrees where one of the two moves is at most two units
long; between longer moves such a turn is a sharp corner, counted apart).
The report of each program is read too: a measured deviation above the
proven bound is counted and its job kept under --found.

Drawings: SVG files under /usr/share (icons, logos, documentation figures
of the machine's Debian packages) scaled so that their larger side is
--size mm, and LibreCAD's part library (package librecad-data) as drawn.
--quick runs the fixed subset the test suite runs (ctest
Sweep.ContoursQuick).

Exit status: 0 when every run ended as above and (with --max-wasted) no
program holds more wasted blocks than allowed; 1 otherwise; 77 when none
of the drawings is on this machine.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor

# The fixed subset the test suite runs: drawings whose contours exercise
# split offsets, narrow gaps, small kinks and sharp inner corners, with the
# contours that matter picked out by index (None: every closed contour).
ICONS = "/usr/share/icons/Adwaita/scalable/actions/"
HERE = os.path.dirname(os.path.abspath(__file__))
QUICK = [
    # letters of two logos: the G's offset falls apart outside (its mouth
    # is narrower than a 6 mm tool), the x has sharp inner corners
    (os.path.join(HERE, "..", "cam", "data", "part-letter-g.json"), None),
    (os.path.join(HERE, "..", "cam", "data", "part-letter-x.json"), None),
    # outlines that turn back on themselves: a spur of zero width, a cusp, curls
    (ICONS + "document-open-symbolic.svg", {0, 1}),
    (ICONS + "document-print-preview-symbolic.svg", {3}),
    (ICONS + "font-select-symbolic.svg", {2}),
    (ICONS + "tools-check-spelling-symbolic.svg", {0}),
]
QUICK_TOOLS = "1,6"
QUICK_SUBSET_EVERY = 3

# The refusals a run may end in: a tool that fits nowhere on the side asked,
# a drawing larger than the machine's travel (LibreCAD's building plans on
# the Fanuc profile).
REFUSALS = ("job.cut", "program.travel")

LINE = re.compile(r"\(.*?\)|;.*")
WORD = re.compile(r"([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))")


def program_moves(text):
    """XY feed moves of a G-code program: (from, to, start direction, end direction)."""
    out = []
    pos = {"X": None, "Y": None, "Z": None}
    mode = None
    for raw in text.splitlines():
        line = LINE.sub("", raw).upper()
        words = WORD.findall(line)
        if not words:
            continue
        vals = {}
        for letter, num in words:
            if letter == "G":
                g = float(num)
                if g in (0, 1, 2, 3):
                    mode = int(g)
                elif g in (5.2, 6.2):
                    mode = None  # a NURBS block: its points are not moves of their own
            elif letter not in vals:
                vals[letter] = float(num)
        if not any(k in vals for k in "XYZ"):
            continue
        new = {k: vals.get(k, pos[k]) for k in "XYZ"}
        if None not in (pos["X"], pos["Y"]) and mode in (1, 2, 3):
            a = (pos["X"], pos["Y"])
            b = (new["X"], new["Y"])
            if a != b:
                if mode == 1:
                    d0 = d1 = (b[0] - a[0], b[1] - a[1])
                else:
                    c = (a[0] + vals.get("I", 0.0), a[1] + vals.get("J", 0.0))
                    s = 1 if mode == 3 else -1
                    d0 = (-(a[1] - c[1]) * s, (a[0] - c[0]) * s)
                    d1 = (-(b[1] - c[1]) * s, (b[0] - c[0]) * s)
                out.append((a, b, d0, d1))
            elif new["Z"] == pos["Z"]:
                out.append((a, b, (0.0, 0.0), (0.0, 0.0)))  # a move that goes nowhere
            else:
                out.append(None)  # Z only (a plunge, a tab): no XY direction to compare
        else:
            out.append(None)
        pos = new
    return out


def turn_deg(u, v):
    lu, lv = math.hypot(*u), math.hypot(*v)
    if lu == 0 or lv == 0:
        return 0.0
    c = (u[0] * v[0] + u[1] * v[1]) / (lu * lv)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def wasted_blocks(text, unit, reverse_deg):
    """(moves shorter than `unit`, moves doubling back, sharp corners).

    A move that turns back by more than reverse_deg where it meets the
    previous one doubles back when one of the two is at most two units long
    (a crumb of the path, or a rounding that sent a sub-unit piece
    backwards); between longer moves it is a sharp corner of the path (a
    narrow inner corner of a pocket), counted apart."""
    moves = program_moves(text)
    short = back = sharp = 0
    for i, m in enumerate(moves):
        if m is None:
            continue
        if math.dist(m[0], m[1]) < unit * (1 - 1e-6):
            short += 1
        prev = moves[i - 1] if i > 0 else None
        if prev is not None and turn_deg(prev[3], m[2]) > reverse_deg:
            if min(math.dist(m[0], m[1]), math.dist(prev[0], prev[1])) <= 2 * unit * (1 + 1e-6):
                back += 1
            else:
                sharp += 1
    return short, back, sharp


def drawing_extent(job):
    lo = [math.inf, math.inf]
    hi = [-math.inf, -math.inf]

    def walk(x):
        if isinstance(x, list) and len(x) >= 2 and all(isinstance(v, (int, float)) for v in x[:2]):
            for k in range(2):
                lo[k] = min(lo[k], x[k])
                hi[k] = max(hi[k], x[k])
        elif isinstance(x, list):
            for y in x:
                walk(y)

    for e in job["entities"]:
        for s in e.get("segments", []):
            walk(s.get("points", []))
    return max(hi[0] - lo[0], hi[1] - lo[1]) if lo[0] < math.inf else 0.0


def scaled(entity, f):
    e = json.loads(json.dumps(entity))
    for s in e.get("segments", []):
        s["points"] = [[c * f for c in p] for p in s["points"]]
    return e


def contours(bezcam, drawing, size, env):
    """The closed contours of a drawing (or a job file) as entities (scaled for SVG files)."""
    if drawing.lower().endswith(".json"):
        with open(drawing) as f:
            job = json.load(f)
    else:
        r = subprocess.run([bezcam, "import", drawing], capture_output=True, text=True, env=env)
        if r.returncode != 0:
            return None, r.stderr.strip()
        job = json.loads(r.stdout)
    f = 1.0
    if drawing.lower().endswith(".svg") and size > 0:
        ext = drawing_extent(job)
        if ext > 0:
            f = size / ext
    out = []
    for e in job["entities"]:
        if e.get("closed") and e.get("type") == "path":
            out.append(scaled(e, f) if f != 1.0 else e)
    return (job.get("units", "mm"), out), ""


def main():
    root = os.path.dirname(os.path.dirname(HERE))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bezcam", default=os.path.join(root, "build", "bezcam"))
    ap.add_argument("--machines", default=os.path.join(root, "machines"))
    ap.add_argument("--quick", action="store_true", help="the test suite's subset")
    ap.add_argument("--drawings", nargs="*", help="files or folders (default: /usr/share SVG files and LibreCAD's library)")
    ap.add_argument("--size", type=float, default=100.0, help="SVG drawings scaled to this larger side in mm (0: as drawn)")
    ap.add_argument("--tools", default="1,3,6")
    ap.add_argument("--sides", default="outside,inside")
    ap.add_argument("--tolerance-sides", default="both,waste")
    ap.add_argument("--outputs", default="arcs", help="output modes for every contour")
    ap.add_argument("--subset-outputs", default="lines,nurbs", help="output modes for every --subset-every-th contour")
    ap.add_argument("--subset-every", type=int, default=5)
    ap.add_argument("--list-wasted", action="store_true", help="print every program with wasted blocks")
    ap.add_argument("--every", type=int, default=1, help="take every N-th contour only")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--found", default="", help="folder for the jobs of failed runs")
    ap.add_argument("--reverse-deg", type=float, default=150.0)
    ap.add_argument("--max-wasted", type=int, default=-1, help="fail when a program holds more wasted blocks (-1: count only)")
    ap.add_argument("--json", default="", help="write the figures (and every failure) here")
    ap.add_argument("--log", default="", help="append each run's result here as it ends (one JSON line)")
    args = ap.parse_args()

    env = dict(os.environ, BEZCAM_MACHINES=args.machines)
    if args.quick:
        todo = [(os.path.normpath(d), pick) for d, pick in QUICK if os.path.exists(d)]
        args.tools = QUICK_TOOLS
        args.subset_every = QUICK_SUBSET_EVERY
    else:
        paths = args.drawings or ["/usr/share", "/usr/share/librecad/library"]
        todo = []
        for p in paths:
            if os.path.isfile(p):
                todo.append((p, None))
                continue
            for dirpath, _, files in os.walk(p):
                for n in sorted(files):
                    low = n.lower()
                    if low.endswith(".svg") or (low.endswith(".dxf") and "librecad" in dirpath):
                        todo.append((os.path.join(dirpath, n), None))
        todo = sorted(set(todo))
    if not todo:
        print("no drawings on this machine: sweep skipped")
        return 77

    t0 = time.monotonic()
    jobs = []  # (drawing, index, units, entity)
    unread = 0
    for d, pick in todo:
        got, _ = contours(args.bezcam, d, args.size, env)
        if got is None:
            unread += 1
            continue
        units, ents = got
        for i, e in enumerate(ents):
            if pick is None or i in pick:
                jobs.append((d, i, units, e))
    jobs = jobs[:: max(1, args.every)]

    tools = [float(t) for t in args.tools.split(",") if t]
    sides = [s for s in args.sides.split(",") if s]
    tsides = [s for s in args.tolerance_sides.split(",") if s]
    outs = [o for o in args.outputs.split(",") if o]
    subset_outs = [o for o in args.subset_outputs.split(",") if o and o not in outs]
    runs = []
    for k, (d, i, units, e) in enumerate(jobs):
        modes = outs + (subset_outs if k % max(1, args.subset_every) == 0 else [])
        for side in sides:
            for tool in tools:
                for ts in tsides:
                    for out in modes:
                        runs.append((d, i, units, e, side, tool, ts, out))

    tmp = tempfile.mkdtemp(prefix="bezcam-sweep-")
    log_lock = threading.Lock()
    if args.found:
        os.makedirs(args.found, exist_ok=True)

    def run(n_run):
        n, (d, i, units, e, side, tool, ts, out) = n_run
        job = {
            "bezcam": 1,
            "units": units,
            "tolerance": 0.01 if units == "mm" else 0.0004,
            "job": {"feed": 1000, "plunge_feed": 300, "safe_z": 5, "top_z": 0, "cut_z": -1,
                    "tool_diameter": tool if units == "mm" else tool / 25.4, "side": side, "tolerance_side": ts},
            "entities": [e],
        }
        jf = os.path.join(tmp, f"job{n}.json")
        nc = os.path.join(tmp, f"job{n}.nc")
        with open(jf, "w") as f:
            json.dump(job, f)
        machine = "fanuc" if out == "nurbs" else "generic"
        t = time.monotonic()
        rep = os.path.join(tmp, f"job{n}.report.json")
        r = subprocess.run([args.bezcam, "convert", jf, "--output", out, "--machine", machine, "-o", nc, "-q",
                            "--report", rep], capture_output=True, text=True, env=env)
        took = time.monotonic() - t
        res = {"drawing": d, "contour": i, "id": e.get("id", ""), "side": side, "tool": tool, "tolerance_side": ts,
               "output": out, "exit": r.returncode, "time": took, "stderr": r.stderr.strip()[-600:]}
        if r.returncode == 0:
            with open(nc) as f:
                text = f.read()
            dec = 3 if units == "mm" else 4  # generic and fanuc alike
            res["short"], res["back"], res["sharp"] = wasted_blocks(text, 10.0 ** -dec, args.reverse_deg)
            os.remove(nc)
            with open(rep) as f:
                ent = json.load(f)["entities"][0]
            res["measured"], res["proven"] = ent["measured_deviation"], ent["proven_bound"]
            os.remove(rep)
            if res["measured"] > res["proven"] and args.found:
                name = f"above-bound-{os.path.basename(d)}-{i}-{side}-{tool:g}-{ts}-{out}.json"
                with open(os.path.join(args.found, name), "w") as f:
                    json.dump(dict(job, _run={"output": out, "machine": machine, "drawing": d, "contour": i,
                                              "measured": res["measured"], "proven": res["proven"]}), f, indent=1)
        m = re.search(r"error id: ([a-z]+\.[a-z.\-]+)", r.stderr)
        res["error_id"] = m.group(1) if m else ""
        if r.returncode not in (0, 2) or (r.returncode == 2 and res["error_id"] not in REFUSALS):
            if args.found:
                name = f"{os.path.basename(d)}-{i}-{side}-{tool:g}-{ts}-{out}.json"
                with open(os.path.join(args.found, name), "w") as f:
                    json.dump(dict(job, _run={"output": out, "machine": machine, "drawing": d, "contour": i}), f, indent=1)
        os.remove(jf)
        if args.log:
            with log_lock, open(args.log, "a") as f:
                f.write(json.dumps(res) + "\n")
        return res

    with ThreadPoolExecutor(max_workers=max(1, args.workers)) as ex:
        results = list(ex.map(run, enumerate(runs)))
    os.rmdir(tmp)

    by_exit = {}
    for res in results:
        key = str(res["exit"])
        if res["exit"] == 2:
            key += " (refused, " + (res["error_id"] or res["stderr"][:80]) + ")"
        by_exit[key] = by_exit.get(key, 0) + 1
    bad = [r for r in results if r["exit"] not in (0, 2) or (r["exit"] == 2 and r["error_id"] not in REFUSALS)]
    ok = [r for r in results if r["exit"] == 0]
    short = sum(r["short"] for r in ok)
    back = sum(r["back"] for r in ok)
    wasted_progs = [r for r in ok if r["short"] + r["back"] > max(0, args.max_wasted)]
    elapsed = time.monotonic() - t0
    print(f"drawings {len(todo)} ({unread} unreadable), closed contours {len(jobs)}, runs {len(results)}, "
          f"{elapsed:.1f} s ({sum(r['time'] for r in results):.1f} s in bezcam)")
    for k in sorted(by_exit):
        print(f"  exit {k}: {by_exit[k]}")
    sharp = sum(r["sharp"] for r in ok)
    above = [r for r in ok if r["measured"] > r["proven"]]
    print(f"  measured deviation above the proven bound: {len(above)} programs"
          + (f" (largest excess {max(r['measured'] - r['proven'] for r in above):.3g})" if above else ""))
    print(f"  programs written {len(ok)}: moves shorter than the rounding unit {short}, doubling back {back} "
          f"(in {len([r for r in ok if r['short'] + r['back']])} programs); sharp corners turning more than "
          f"{args.reverse_deg:g} degrees {sharp}")
    for r in bad[:20]:
        print(f"  FAILED exit {r['exit']}: {r['drawing']} contour {r['contour']} {r['side']} tool {r['tool']:g} "
              f"{r['tolerance_side']} {r['output']}: {r['stderr'][:300]}")
    if args.list_wasted:
        for r in ok:
            if r["short"] + r["back"]:
                print(f"  wasted: {r['drawing']} contour {r['contour']} {r['side']} tool {r['tool']:g} "
                      f"{r['tolerance_side']} {r['output']}: {r['short']} short, {r['back']} doubling back")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"runs": len(results), "elapsed_s": elapsed, "by_exit": by_exit, "short": short, "back": back, "sharp": sharp, "above_bound": above,
                       "failures": bad, "wasted": [r for r in ok if r["short"] + r["back"]]}, f, indent=1)
    failed = bool(bad) or (args.max_wasted >= 0 and bool(wasted_progs))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
