"""samples/plate-layer0.dxf: a plate drawn the way LibreCAD saves it.

LibreCAD (through libdxfrw) writes DXF 2007 with every entity on layer
"0" unless the user makes layers, a rectangle as four LINEs and a fillet
as an ARC. This script takes a file LibreCAD wrote (from Debian's
librecad-data) and puts a part in its ENTITIES section, in the same
group codes: an 80 x 50 plate with 5 mm corner fillets, four 6.6 mm
holes for M6 screws, a 20 mm bore in the middle and two 3 mm dowel holes,
all on layer "0".

    python3 samples/make_plate_layer0.py [TEMPLATE.dxf]
"""
import sys

template = sys.argv[1] if len(sys.argv) > 1 else "/usr/share/librecad/library/kinetics/kin124.dxf"
lines = open(template).read().split("\n")
begin = lines.index("ENTITIES")
end = next(i for i in range(begin, len(lines)) if lines[i] == "ENDSEC" and lines[i - 1] == "0")

handle = [0x100]


def entity(kind, subclass, fields):
    handle[0] += 1
    out = ["0", kind, "5", "%X" % handle[0], "100", "AcDbEntity", "8", "0", "6", "CONTINUOUS", "62", "7",
           "370", "18", "100", subclass]
    for code, value in fields:
        out += [str(code), ("%.10g" % value) if isinstance(value, float) else str(value)]
    return out


def line(a, b):
    return entity("LINE", "AcDbLine", [(10, float(a[0])), (20, float(a[1])), (11, float(b[0])), (21, float(b[1]))])


def circle(cx, cy, d):
    return entity("CIRCLE", "AcDbCircle", [(10, float(cx)), (20, float(cy)), (40, d / 2.0)])


def arc(cx, cy, r, a0, a1):
    e = entity("ARC", "AcDbCircle", [(10, float(cx)), (20, float(cy)), (40, float(r))])
    return e + ["100", "AcDbArc", "50", "%.10g" % a0, "51", "%.10g" % a1]


W, H, R = 80, 50, 5
ents = []
ents += line((R, 0), (W - R, 0)) + arc(W - R, R, R, 270, 360)
ents += line((W, R), (W, H - R)) + arc(W - R, H - R, R, 0, 90)
ents += line((W - R, H), (R, H)) + arc(R, H - R, R, 90, 180)
ents += line((0, H - R), (0, R)) + arc(R, R, R, 180, 270)
for x, y in ((8, 8), (W - 8, 8), (W - 8, H - 8), (8, H - 8)):
    ents += circle(x, y, 6.6)
ents += circle(W / 2, H / 2, 20)
ents += circle(W / 2 - 18, H / 2, 3) + circle(W / 2 + 18, H / 2, 3)

out = lines[: begin + 1] + ents + lines[end - 1:]
open("samples/plate-layer0.dxf", "w").write("\n".join(out))
