#!/usr/bin/env python3
"""FreeCAD's Adaptive clearing on the pockets of cases.json, as its Path
workbench runs it (the libarea Adaptive2d that the Adaptive operation
calls, with the operation's default settings), written as G-code that
bezcam's check reads (bench/pocket_peer.sh).

    python3 freecad_adaptive.py CASES.json OUTDIR

For each case: OUTDIR/<index>.freecad.ngc, and one line of JSON on stdout
with the case's index and the seconds Adaptive2d.Execute took. Needs
Debian's freecad package (its area module).
"""
import json
import math
import sys
import time

sys.path.append("/usr/lib/freecad-python3/lib")
import area  # noqa: E402  (FreeCAD's libarea)

SAG = 0.001  # circles as polygons within this of the circle
SAFE_Z = 5.0
FEED, PLUNGE_FEED = 1000.0, 300.0
HELIX_ANGLE_DEG = 5.0  # the operation's default


def loop_points(loop):
    if isinstance(loop, dict):
        cx, cy, r = loop["circle"]
        n = max(8, math.ceil(math.pi / math.acos(1 - SAG / r)))
        return [[cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n)] for k in range(n)]
    return [list(p) for p in loop]


def num(v):
    return "%.4f" % v


class Program:
    def __init__(self):
        self.lines = ["G21 G90 G17", "G0 Z%s" % num(SAFE_Z)]
        self.z = SAFE_Z

    def rapid(self, x=None, y=None, z=None):
        words = []
        if x is not None:
            words += ["X" + num(x), "Y" + num(y)]
        if z is not None:
            words.append("Z" + num(z))
            self.z = z
        self.lines.append("G0 " + " ".join(words))

    def feed(self, code, words, f):
        self.lines.append(code + " " + " ".join(words) + " F" + num(f))


def helix_entry(prog, centre, start, cut_z):
    """Down to cut_z on a helix around the Adaptive result's helix centre,
    through its start point's radius, then one full circle at depth, as the
    operation's G-code generator does for a single depth."""
    r = math.hypot(start[0] - centre[0], start[1] - centre[1])
    if r <= 0.01:
        prog.rapid(start[0], start[1])
        prog.feed("G1", ["Z" + num(cut_z)], PLUNGE_FEED)
        prog.z = cut_z
        return
    r -= 0.01
    x, y = centre[0] + r, centre[1]
    prog.rapid(x, y)
    prog.rapid(z=0.5)
    per_turn = 2 * math.pi * r * math.tan(math.radians(HELIX_ANGLE_DEG))
    z = 0.5
    while z - per_turn > cut_z:
        prog.feed("G2", ["X" + num(x - 2 * r), "Y" + num(y), "Z" + num(z - per_turn / 2), "I" + num(-r)], PLUNGE_FEED)
        prog.feed("G2", ["X" + num(x), "Y" + num(y), "Z" + num(z - per_turn), "I" + num(r)], PLUNGE_FEED)
        z -= per_turn
    prog.feed("G2", ["X" + num(x - 2 * r), "Y" + num(y), "Z" + num((z + cut_z) / 2), "I" + num(-r)], PLUNGE_FEED)
    prog.feed("G2", ["X" + num(x), "Y" + num(y), "Z" + num(cut_z), "I" + num(r)], PLUNGE_FEED)
    prog.feed("G2", ["X" + num(x - 2 * r), "Y" + num(y), "I" + num(-r)], FEED)
    prog.feed("G2", ["X" + num(x), "Y" + num(y), "I" + num(r)], FEED)
    prog.z = cut_z


def run(case, cut_z):
    paths = [loop_points(l) for l in case["loops"]]
    xs = [p[0] for l in paths for p in l]
    ys = [p[1] for l in paths for p in l]
    stock = [[[min(xs) - 5, min(ys) - 5], [max(xs) + 5, min(ys) - 5], [max(xs) + 5, max(ys) + 5],
              [min(xs) - 5, max(ys) + 5]]]
    a2d = area.Adaptive2d()
    a2d.stepOverFactor = case["load"] / case["tool_diameter"]
    a2d.toolDiameter = case["tool_diameter"]
    a2d.helixRampDiameter = 0.0  # the operation's default (no limit)
    a2d.keepToolDownDistRatio = 3.0
    a2d.stockToLeave = 0.0
    a2d.tolerance = 0.1  # the operation's default "accuracy vs performance"
    a2d.forceInsideOut = False
    a2d.finishingProfile = True
    a2d.opType = area.AdaptiveOperationType.ClearingInside
    t0 = time.perf_counter()
    results = a2d.Execute(stock, paths, lambda tpaths: False)
    seconds = time.perf_counter() - t0

    prog = Program()
    for res in results:
        helix_entry(prog, res.HelixCenterPoint, res.StartPoint, cut_z)
        z = cut_z
        for kind, pts in res.AdaptivePaths:
            for x, y in pts:
                if kind == area.AdaptiveMotionType.Cutting:
                    if prog.z != cut_z:
                        prog.feed("G1", ["Z" + num(cut_z)], PLUNGE_FEED)
                        prog.z = cut_z
                    prog.feed("G1", ["X" + num(x), "Y" + num(y)], FEED)
                elif kind == area.AdaptiveMotionType.LinkClear:
                    if prog.z != cut_z:  # the operation's lift distance is 0
                        prog.feed("G1", ["Z" + num(cut_z)], PLUNGE_FEED)
                        prog.z = cut_z
                    prog.rapid(x, y)
                else:  # LinkNotClear: over the top
                    if prog.z != SAFE_Z:
                        prog.rapid(z=SAFE_Z)
                    prog.rapid(x, y)
        if prog.z != SAFE_Z:
            prog.rapid(z=SAFE_Z)
    prog.lines.append("M2")
    return seconds, "\n".join(prog.lines) + "\n"


def main():
    doc = json.load(open(sys.argv[1]))
    out = sys.argv[2]
    for i, case in enumerate(doc["cases"]):
        seconds, text = run(case, doc["cut_z"])
        with open("%s/%d.freecad.ngc" % (out, i), "w") as f:
            f.write(text)
        print(json.dumps({"case": i, "seconds": seconds}))


if __name__ == "__main__":
    main()
