#!/usr/bin/python3
"""Writes the synthetic programs of the LinuxCNC anchor (this folder's *.ngc).

    /usr/bin/python3 tests/lcnc/programs/make_programs.py

The files are kept in the repository; this script documents how they were
made and rewrites them identically. Every program starts with G0 X0 Y0 Z0:
LinuxCNC is there already (homed in place), and bezcam's simulator, which
starts at an unknown position and times no move out of it, starts there too.

  chords-<c>-F<f>  a circle R20 (centre -20,0, through the origin) as G1
                   chords of c mm, at feed f mm/min
  arc-F<f>         the same circle as one G2
  nurbs-F<f>       the same circle as four G5.2 rational quarters
  wave-F<f>        a G5.2 cubic NURBS with 8 control points (uniform knots)
  square-F<f>      a 40 mm square of G1 (blended corners)
  square-g61-F<f>  the same square in G61 (exact stop, the program's mode wins)
  pocket-3d        rapids, a Z plunge, lines and arcs at several feeds
  limits-g61       single-axis G0 moves in exact stop, each reaching its
                   axis's top speed: anchor.py checks on it that LinuxCNC
                   runs at the profile's limits (the harness configured them)
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
R = 20.0
CX, CY = -R, 0.0  # circle centre; the circle passes through the origin


def fmt(v):
    s = "%.4f" % v
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def write(name, lines, comment):
    with open(os.path.join(HERE, name + ".ngc"), "w") as f:
        f.write("(%s)\n" % comment)
        f.write("G21 G90 G17 G94\n")
        f.write("G0 X0 Y0 Z0\n")
        f.write("\n".join(lines) + "\n")
        f.write("M2\n")


def chords(chord, feed):
    n = int(math.ceil(2 * math.pi * R / chord))
    out = ["F%d" % feed]
    for i in range(1, n + 1):
        a = -2 * math.pi * i / n  # clockwise from angle 0 (the origin)
        out.append("G1 X%s Y%s" % (fmt(CX + R * math.cos(a)), fmt(CY + R * math.sin(a))))
    out[-1] = "G1 X0 Y0"
    write("chords-%s-F%d" % (fmt(chord), feed), out,
          "circle R%g as %d G1 chords of %g mm, F%d" % (R, n, chord, feed))


def arc(feed):
    write("arc-F%d" % feed, ["G2 X0 Y0 I%s J0 F%d" % (fmt(CX), feed)],
          "circle R%g as one G2, F%d" % (R, feed))


def nurbs(feed):
    w = fmt(math.sqrt(0.5))
    # clockwise quarters, like G2: (0,0) -> (-20,-20) -> (-40,0) -> (-20,20) -> (0,0)
    pts = [(0, 0), (CX, -R), (CX - R, 0), (CX, R), (0, 0)]
    corners = [(0, -R), (CX - R, -R), (CX - R, R), (0, R)]
    out = []
    for q in range(4):
        out.append("G5.2 P1 L3" + (" F%d" % feed if q == 0 else ""))
        out.append("X%s Y%s P%s" % (fmt(corners[q][0]), fmt(corners[q][1]), w))
        out.append("X%s Y%s P1" % (fmt(pts[q + 1][0]), fmt(pts[q + 1][1])))
        out.append("G5.3")
    write("nurbs-F%d" % feed, out,
          "circle R%g as four G5.2 rational quarters, F%d" % (R, feed))


def wave(feed):
    pts = [(10, 15), (20, -15), (30, 15), (40, -15), (50, 15), (60, -15), (70, 0)]
    out = ["G5.2 P1 L4 F%d" % feed]
    out += ["X%s Y%s P1" % (fmt(x), fmt(y)) for x, y in pts]
    out += ["G5.3", "G1 X0 Y0"]
    write("wave-F%d" % feed, out,
          "a cubic G5.2 through 8 control points then back in G1, F%d" % feed)


def square(feed, g61=False):
    out = (["G61"] if g61 else []) + ["G1 X40 Y0 F%d" % feed, "G1 X40 Y40",
                                      "G1 X0 Y40", "G1 X0 Y0"]
    write("square-%sF%d" % ("g61-" if g61 else "", feed), out,
          "a 40 mm square of G1, F%d%s" % (feed, ", exact stop: G61" if g61 else ""))


def pocket():
    out = ["G0 Z5", "G0 X10 Y10", "G1 Z-1 F300",
           "G1 X50 F4000", "G3 X50 Y30 I0 J10", "G1 X10", "G2 X10 Y10 I0 J-10",
           "G1 X30 Y20 Z-2 F2000", "G1 X45 Y20 F6000",
           "G0 Z5", "G0 X0 Y0", "G0 Z0"]
    write("pocket-3d", out, "rapids, a Z plunge, lines and arcs, ramp in Z, several feeds")


# axis, signed length of each G0 of limits-g61
LIMIT_MOVES = [("x", 100.0), ("y", -40.0), ("z", -50.0), ("z", 50.0), ("y", 40.0),
               ("x", -100.0)]


def limits():
    pos = {"x": 0.0, "y": 0.0, "z": 0.0}
    out = ["G61"]
    for axis, d in LIMIT_MOVES:
        pos[axis] += d
        out.append("G0 %s%s" % (axis.upper(), fmt(pos[axis])))
    write("limits-g61", out, "single-axis rapids in exact stop: G61")


if __name__ == "__main__":
    limits()
    for f in (3000, 9000):
        chords(0.05, f)
    for f in (3000, 6000, 9000):
        chords(0.5, f)
    for f in (1500, 3000, 9000):
        arc(f)
    for f in (3000, 6000, 9000):
        nurbs(f)
    for f in (3000, 9000):
        wave(f)
    square(3000)
    square(6000, g61=True)
    pocket()
