# Writes a DXF with ezdxf (argv[1]) and, in argv[2], points ezdxf itself
# evaluates on each entity ("LAYER x y" per line): the reference the
# imported geometry must pass through (tests/import/dxf_reader_test.cpp).
import math
import sys

import ezdxf
from ezdxf.math import bulge_to_arc

doc = ezdxf.new("R2010")
doc.header["$INSUNITS"] = 4  # mm
msp = doc.modelspace()
ref = []


def add(layer, pts):
    ref.extend((layer, p[0], p[1]) for p in pts)


def sample(e, layer):
    t = e.dxftype()
    if t == "LINE":
        s, en = e.dxf.start, e.dxf.end
        add(layer, [s, en, s.lerp(en, 0.37)])
    elif t == "CIRCLE":
        add(layer, e.vertices([i * 360 / 17 for i in range(17)]))
    elif t == "ARC":
        a0, a1 = e.dxf.start_angle, e.dxf.end_angle
        if a1 < a0:
            a1 += 360
        add(layer, e.vertices([a0 + (a1 - a0) * i / 12 for i in range(13)]))
    elif t == "ELLIPSE":
        c = e.construction_tool()
        add(layer, c.vertices(c.params(25)))
    elif t == "SPLINE":
        add(layer, e.construction_tool().approximate(60))
    elif t == "POLYLINE":
        for v in e.virtual_entities():
            sample(v, layer)
    elif t == "LWPOLYLINE":
        ocs = e.ocs()
        pts = list(e.get_points("xyb"))
        n = len(pts)
        for i in range(n if e.closed else n - 1):
            x0, y0, b = pts[i]
            x1, y1, _ = pts[(i + 1) % n]
            z = e.dxf.elevation
            if b == 0:
                loc = [(x0 + (x1 - x0) * k / 5, y0 + (y1 - y0) * k / 5, z) for k in range(6)]
            else:
                c, a0, a1, r = bulge_to_arc((x0, y0), (x1, y1), b)
                if a1 < a0:
                    a1 += 2 * math.pi
                loc = [(c[0] + r * math.cos(a0 + (a1 - a0) * k / 10), c[1] + r * math.sin(a0 + (a1 - a0) * k / 10), z)
                       for k in range(11)]
            add(layer, list(ocs.points_to_wcs(loc)))
    elif t == "INSERT":
        for v in e.virtual_entities():
            sample(v, layer)


# A rational clamped cubic spline.
s = msp.add_rational_spline([(0, 0), (10, 20), (30, -5), (45, 15), (60, 0)], [1, 0.5, 2, 1, 0.8], degree=3,
                            dxfattribs={"layer": "SPLINE"})
# A spline by fit points and end tangents (no control points in the file):
# CAD programs' global interpolation, evaluated by ezdxf.
f = msp.add_spline([(0, 60), (12, 75), (30, 62), (41, 80), (55, 66)], dxfattribs={"layer": "FIT"})
f.dxf.start_tangent = (1, 2, 0)
f.dxf.end_tangent = (1, -0.5, 0)
# A partial, rotated ellipse.
msp.add_ellipse((100, 50), major_axis=(20, 10), ratio=0.4, start_param=0.3, end_param=4.0, dxfattribs={"layer": "ELLIPSE"})
# A closed polyline with bulges of both signs.
msp.add_lwpolyline([(0, 100, 0.5), (30, 100, -1), (60, 100, 0), (60, 130, 0.3)], format="xyb", close=True,
                   dxfattribs={"layer": "POLY"})
# Object coordinate systems: an arc and a bulged polyline drawn with
# extrusion (0, 0, -1) (mirrored in x, as CAD shows them), an old-style 2D
# POLYLINE with bulges.
msp.add_arc((30, -40), 12, 10, 160, dxfattribs={"layer": "OCS", "extrusion": (0, 0, -1)})
msp.add_lwpolyline([(60, -40, 0.4), (80, -40, 0), (80, -20, -0.7)], format="xyb",
                   dxfattribs={"layer": "OCS", "extrusion": (0, 0, -1), "elevation": 2})
p2 = msp.add_polyline2d([(100, -40), (120, -40), (120, -20)], dxfattribs={"layer": "POLY2D"})
p2.vertices[0].dxf.bulge = 0.5
p2.vertices[1].dxf.bulge = -0.25
# A block (circle, arc, line) inserted rotated and mirrored, scaled unevenly.
b = doc.blocks.new("B", base_point=(5, 5))
b.add_circle((10, 10), 4)
b.add_arc((0, 0), 8, 20, 150)
b.add_line((-5, -5), (15, 0))
msp.add_blockref("B", (200, 50), dxfattribs={"layer": "INS", "rotation": 30, "xscale": -1, "yscale": 2})
msp.add_blockref("B", (150, 150), dxfattribs={"layer": "INS2", "rotation": 200, "xscale": 1.5, "yscale": 1.5})

for e in msp:
    sample(e, e.dxf.layer)
doc.saveas(sys.argv[1])
with open(sys.argv[2], "w") as f:
    for layer, x, y in ref:
        f.write(f"{layer} {x!r} {y!r}\n")
