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
  g64-chords-0.5-F<f>  the chords circle under G64 without P (blend as fast
                   as the planner can: no path tolerance)
  g64-square-F<f>  the square under G64 without P
  arcs-s-F<f>      G2/G3 arcs of 10 and 20 mm radius meeting tangentially
  arcs-kinked-<k>-F<f>  G3/G2 arcs of R10 and 60 degrees turning opposite
                   ways, each joint a kink of k rad (0.01: LinuxCNC blends
                   them by arcs; 0.45: by parabolic blends)
  chain-F<f>       lines and arcs of 1 to 60 mm radius, tangent or meeting
                   at kinks of up to 1.5 rad (a fixed pseudo-random chain)
  helix-ramp-F<f>  arcs running into a Z ramp and out of it, and a helix
  dxf2gcode-plate-F<f>   a plate in dxf2gcode's LinuxCNC layout (G64
                   without P, the feed on a line of its own, padded words)
  dxf2gcode-spline-F<f>  a sine as three-point arcs, each fitted alone, so
                   that neighbours meet at small kinks (as older arc fitters
                   write a spline), dxf2gcode's layout
  freecad-profile-F<f>   a rounded rectangle in three depth passes in
                   FreeCAD's linuxcnc_post layout (every word repeated, F
                   on every line, G2 with I J K)
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


def write_raw(name, text):
    with open(os.path.join(HERE, name + ".ngc"), "w") as f:
        f.write(text)


def g64_chords(chord, feed):
    n = int(math.ceil(2 * math.pi * R / chord))
    out = ["G64", "F%d" % feed]
    for i in range(1, n + 1):
        a = -2 * math.pi * i / n
        out.append("G1 X%s Y%s" % (fmt(CX + R * math.cos(a)), fmt(CY + R * math.sin(a))))
    out[-1] = "G1 X0 Y0"
    write("g64-chords-%s-F%d" % (fmt(chord), feed), out,
          "circle R%g as %d G1 chords of %g mm under G64 without P, F%d" % (R, n, chord, feed))


def g64_square(feed):
    out = ["G64", "G1 X40 Y0 F%d" % feed, "G1 X40 Y40", "G1 X0 Y40", "G1 X0 Y0"]
    write("g64-square-F%d" % feed, out, "a 40 mm square of G1 under G64 without P, F%d" % feed)


def arcs_s(feed):
    # tangent: two half circles of R10 forming an S, then a quarter of R20
    out = ["G1 X10 Y0 F%d" % feed,
           "G3 X10 Y20 I0 J10", "G2 X10 Y40 I0 J10",
           "G3 X30 Y60 I0 J20", "G2 X50 Y60 I10 J0", "G3 X70 Y60 I10 J0",
           "G1 X0 Y0"]
    write("arcs-s-F%d" % feed, out, "G2/G3 arcs meeting tangentially, F%d" % feed)


def arcs_kinked(kink, feed):
    x = y = h = 0.0
    out = ["G1 X0 Y0 Z-1 F300", "F%d" % feed]
    for i in range(20):
        s = 1 if i % 2 == 0 else -1  # G3, then G2
        cx, cy = x - s * 10 * math.sin(h), y + s * 10 * math.cos(h)
        h += s * math.radians(60)
        ex, ey = cx + s * 10 * math.sin(h), cy - s * 10 * math.cos(h)
        out.append("%s X%s Y%s I%s J%s" % ("G3" if s > 0 else "G2", fmt(ex), fmt(ey), fmt(cx - x), fmt(cy - y)))
        x, y = ex, ey
        h += s * kink
    out.append("G0 Z5")
    write("arcs-kinked-%s-F%d" % (fmt(kink), feed), out,
          "R10 arcs turning opposite ways with kinks of %s rad, F%d" % (fmt(kink), feed))


def chain(feed):
    # a linear congruential generator: the same chain on every Python
    state = [12345]

    def rnd():
        state[0] = (1103515245 * state[0] + 12345) % 2**31
        return state[0] / 2**31

    x = y = h = 0.0
    out = ["G1 X0 Y0 Z-1 F300", "F%d" % feed]
    for _ in range(25):
        if rnd() < 0.3:
            length = 0.5 + 14.5 * rnd()
            x, y = x + length * math.cos(h), y + length * math.sin(h)
            out.append("G1 X%s Y%s" % (fmt(x), fmt(y)))
        else:
            r = 1 + 4 * rnd() if rnd() < 0.5 else 5 + 55 * rnd()
            sweep = 0.1 + 1.7 * rnd()
            s = 1 if rnd() < 0.5 else -1
            cx, cy = x - s * r * math.sin(h), y + s * r * math.cos(h)
            h += s * sweep
            ex, ey = cx + s * r * math.sin(h), cy - s * r * math.cos(h)
            out.append("%s X%s Y%s I%s J%s" % ("G3" if s > 0 else "G2", fmt(ex), fmt(ey), fmt(cx - x), fmt(cy - y)))
            x, y = ex, ey
        u = rnd()
        if u >= 0.3:
            span = (0.002, 0.05, 0.6, 1.5)[int(4 * rnd()) % 4]
            h += span * (2 * rnd() - 1)
    out.append("G0 Z5")
    write("chain-F%d" % feed, out, "lines and arcs, tangent or at kinks, F%d" % feed)


def helix_ramp(feed):
    out = ["G1 X20 Y0 F%d" % feed,
           "G3 X40 Y20 I0 J20",          # arc in the plane
           "G1 X40 Y40 Z-2",             # straight into a Z ramp
           "G3 X20 Y60 I-20 J0 Z-2",     # out of the ramp into an arc
           "G2 X0 Y40 I0 J-20 Z-4",      # a helix turn down
           "G1 X0 Y20 Z-4",
           "G2 X0 Y20 I10 J0 Z-6",       # a full helical turn
           "G1 X0 Y0 Z0"]
    write("helix-ramp-F%d" % feed, out, "arcs into and out of a Z ramp, helices, F%d" % feed)


def pad(v):
    return "%8.3f" % v


def dxf2gcode_head(comment):
    return ("(%s)\n(Generated in the layout of dxf2gcode's LinuxCNC export)\n"
            "G21 (Units in millimeters)  G90 (Absolute programming)\n"
            "G64 (Default cutting) G17 (XY plane) G40 (Cancel radius comp.) "
            "G49 (Cancel length comp.)\nG0 X0 Y0 Z0\n" % comment)


def dxf2gcode_plate(feed):
    t = dxf2gcode_head("a 80 x 50 plate with R8 corners and a slot, F%d" % feed)
    t += "(* SHAPE Nr: 0 *)\nG0 X%s Y%s\nG0 Z%s \nF300\nG1 Z%s\nF%d\n" % (
        pad(8), pad(0), pad(5), pad(-1.5), feed)
    for w in ["G1 X%s Y%s" % (pad(72), pad(0)),
              "G3 X%s Y%s I%s J%s" % (pad(80), pad(8), pad(0), pad(8)),
              "G1 X%s Y%s" % (pad(80), pad(42)),
              "G3 X%s Y%s I%s J%s" % (pad(72), pad(50), pad(-8), pad(0)),
              "G1 X%s Y%s" % (pad(8), pad(50)),
              "G3 X%s Y%s I%s J%s" % (pad(0), pad(42), pad(0), pad(-8)),
              "G1 X%s Y%s" % (pad(0), pad(8)),
              "G3 X%s Y%s I%s J%s" % (pad(8), pad(0), pad(8), pad(0))]:
        t += w + "\n"
    t += "F300\nG0 Z%s \n" % pad(5)
    t += "(* SHAPE Nr: 1 *)\nG0 X%s Y%s\nG0 Z%s \nF300\nG1 Z%s\nF%d\n" % (
        pad(25), pad(20), pad(5), pad(-1.5), feed)
    for w in ["G1 X%s Y%s" % (pad(55), pad(20)),
              "G3 X%s Y%s I%s J%s" % (pad(55), pad(30), pad(0), pad(5)),
              "G1 X%s Y%s" % (pad(25), pad(30)),
              "G3 X%s Y%s I%s J%s" % (pad(25), pad(20), pad(0), pad(-5))]:
        t += w + "\n"
    t += "F300\nG0 Z%s \nG0 X0 Y0\nG0 Z0\nM2 (Program end)\n" % pad(5)
    write_raw("dxf2gcode-plate-F%d" % feed, t)


def circle3(p, q, r):
    (ax, ay), (bx, by), (cx, cy) = p, q, r
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return ux, uy, d > 0


def dxf2gcode_spline(feed):
    # y = 10 sin(x / 8), x from 0 to 100: 25 arcs, each through its two ends
    # and the curve's midpoint, fitted alone (neighbours meet at small kinks)
    f = lambda x: (x, 10 * math.sin(x / 8.0))
    t = dxf2gcode_head("a sine as 25 three-point arcs meeting at kinks, F%d" % feed)
    t += "(* SHAPE Nr: 0 *)\nG0 X%s Y%s\nG0 Z%s \nF300\nG1 Z%s\nF%d\n" % (
        pad(0), pad(0), pad(5), pad(-1), feed)
    n = 25
    for i in range(n):
        x0, x1 = 100.0 * i / n, 100.0 * (i + 1) / n
        p, m, q = f(x0), f((x0 + x1) / 2), f(x1)
        ux, uy, ccw = circle3(p, m, q)
        t += "%s X%s Y%s I%s J%s\n" % ("G3" if ccw else "G2", pad(q[0]), pad(q[1]),
                                       pad(ux - p[0]), pad(uy - p[1]))
    t += "F300\nG0 Z%s \nG0 X0 Y0\nG0 Z0\nM2 (Program end)\n" % pad(5)
    write_raw("dxf2gcode-spline-F%d" % feed, t)


def freecad_profile(feed):
    t = ("(Exported in the layout of FreeCAD's linuxcnc_post)\n(begin preamble)\n"
         "G17 G54 G40 G49 G80 G90\nG21\nG0 X0 Y0 Z0\n(begin operation: Profile)\n"
         "(machine units: mm/min)\n(Profile)\n(Compensated Tool Path. Diameter: 6.0)\n"
         "G0 Z15.000\nG0 X-3.000 Y0.000\nG0 Z3.000\n")
    for z in (-1.0, -2.0, -3.0):
        Z = "%.3f" % z
        F = "%.3f" % feed
        t += "G1 X-3.000 Y0.000 Z%s F%.3f\n" % (Z, feed / 4.0)
        for w in ["G1 X-3.000 Y40.000", "G2 X0.000 Y43.000 I3.000 J0.000",
                  "G1 X60.000 Y43.000", "G2 X63.000 Y40.000 I0.000 J-3.000",
                  "G1 X63.000 Y0.000", "G2 X60.000 Y-3.000 I-3.000 J0.000",
                  "G1 X0.000 Y-3.000", "G2 X-3.000 Y0.000 I0.000 J3.000"]:
            parts = w.split(" ", 3)
            t += "%s %s %s Z%s%s F%s\n" % (parts[0], parts[1], parts[2], Z,
                                            (" " + parts[3]) if len(parts) > 3 else "", F)
    t += "G0 Z15.000\nG0 X0.000 Y0.000\nG0 Z0.000\n(finish operation: Profile)\nM2\n"
    write_raw("freecad-profile-F%d" % feed, t)


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
    g64_chords(0.5, 6000)
    g64_square(6000)
    arcs_s(6000)
    arcs_kinked(0.01, 6000)
    arcs_kinked(0.45, 6000)
    chain(9000)
    helix_ramp(3000)
    dxf2gcode_plate(3000)
    dxf2gcode_spline(4000)
    freecad_profile(2400)
