# Reads DXF files with ezdxf, independently of bezcam, and writes points
# ezdxf evaluates on every curve entity: for each DXF named in argv[1] (one
# path a line), argv[2]/<index>.ref holds "$INSUNITS <code>" then "x y"
# lines in drawing units (tests/import/dxf_reader_test.cpp).
import math
import sys

import ezdxf
from ezdxf.math import bulge_to_arc


def sample(e, out):
    t = e.dxftype()
    if t == "LINE":
        s, en = e.dxf.start, e.dxf.end
        out += [s, en, s.lerp(en, 0.37)]
    elif t == "CIRCLE":
        if e.dxf.radius > 0:
            out += list(e.vertices([i * 360 / 7 for i in range(7)]))
    elif t == "ARC":
        if e.dxf.radius > 0:
            a0, a1 = e.dxf.start_angle, e.dxf.end_angle
            if a1 < a0:
                a1 += 360
            out += list(e.vertices([a0 + (a1 - a0) * i / 6 for i in range(7)]))
    elif t == "ELLIPSE":
        c = e.construction_tool()
        out += list(c.vertices(c.params(9)))
    elif t == "SPLINE":
        if e.control_point_count() or (e.dxf.hasattr("start_tangent") and e.dxf.hasattr("end_tangent")):
            out += list(e.construction_tool().approximate(12))
    elif t == "LWPOLYLINE":
        ocs = e.ocs()
        pts = list(e.get_points("xyb"))
        n = len(pts)
        for i in range(n if e.closed else n - 1):
            x0, y0, b = pts[i]
            x1, y1, _ = pts[(i + 1) % n]
            z = e.dxf.elevation
            if b == 0:
                loc = [(x0 + (x1 - x0) * k / 3, y0 + (y1 - y0) * k / 3, z) for k in range(4)]
            else:
                c, a0, a1, r = bulge_to_arc((x0, y0), (x1, y1), b)
                if a1 < a0:
                    a1 += 2 * math.pi
                loc = [(c[0] + r * math.cos(a0 + (a1 - a0) * k / 4), c[1] + r * math.sin(a0 + (a1 - a0) * k / 4), z)
                       for k in range(5)]
            out += list(ocs.points_to_wcs(loc))
    elif t in ("POLYLINE", "INSERT"):
        if t == "POLYLINE" and (e.is_polygon_mesh or e.is_poly_face_mesh):
            return
        for v in e.virtual_entities():
            sample(v, out)


files = [l.strip() for l in open(sys.argv[1]) if l.strip()]
for i, name in enumerate(files):
    doc = ezdxf.readfile(name)
    pts = []
    for e in doc.modelspace():
        try:
            sample(e, pts)
        except Exception:  # what ezdxf cannot evaluate is not compared
            pass
    with open(f"{sys.argv[2]}/{i}.ref", "w") as f:
        f.write(f"$INSUNITS {doc.header.get('$INSUNITS', 0)}\n")
        for p in pts:
            f.write(f"{p[0]!r} {p[1]!r}\n")
