# Reads SVG files with svgelements (python3-svgelements), independently of
# bezcam, and writes what svgelements makes of every shape's geometry once
# every transform, the viewBox and preserveAspectRatio are applied: for each
# SVG named in argv[1] (one path a line), argv[2]/<index>.ref holds
#   page <height in px>
# then per subpath of each element with an id
#   subpath <id> <open|closed> <length in px>
# followed by "x y" lines in px, y down (96 px per inch): the subpath's start,
# points at nine parameters of every segment, and its end
# (tests/import/svg_reader_test.cpp).
import re
import sys

import svgelements as se


def rounding(svg):
    """svgelements converts mm and cm with 0.0393701 inch per mm (six figures):
    under a page sized in mm or cm every coordinate it gives is that much
    larger than the 96 px per inch of the SVG specification. The factor, to
    divide out (1 for px and in)."""
    units = set()
    for a in ("width", "height"):
        m = re.fullmatch(r"\s*[-+0-9.eE]+\s*([a-z]*)\s*", svg.values.get(a) or "")
        if m:
            units.add(m.group(1))
    if units & {"mm", "cm"}:
        assert units <= {"mm", "cm"}, "a page sized in mm and another unit"
        return 0.0393701 * 25.4
    return 1.0


def subpaths(shape):
    """(closed, segments) of each subpath that draws something, in the
    shape's own coordinates (before its transform)."""
    path = shape if isinstance(shape, se.Path) else se.Path(shape)
    runs = [[]]
    for s in path.segments(transformed=False):
        if isinstance(s, se.Move):
            runs.append([])
        else:
            runs[-1].append(s)
    for segs in runs:
        drawn = [s for s in segs if s.start != s.end]  # a zero-length close or arc draws nothing
        if drawn:
            yield any(isinstance(s, se.Close) for s in segs), drawn


def length(seg, m):
    """Length of the segment's image under m: polylines of 128 and 256
    chords, Richardson-extrapolated (error well below 1e-9 of the length)."""
    def poly(n):
        pts = [m.point_in_matrix_space(seg.point(k / n)) for k in range(n + 1)]
        return sum(abs(b - a) for a, b in zip(pts, pts[1:]))
    return (4 * poly(256) - poly(128)) / 3


def shapes(group, prefix):
    """(id, shape) of every shape with an id under `group`, depth first. svgelements
    puts what a `use` draws right after the use: its ids get the use's id and
    a slash in front, as bezcam names them."""
    uses = ""
    for e in group:
        if type(e) is se.SVGElement and e.values.get("tag") == "use":
            uses += (e.id or "use") + "/"
            continue
        if isinstance(e, se.Shape) and e.id:
            yield prefix + uses + e.id, e
        if isinstance(e, se.Group):
            yield from shapes(e, prefix + uses)
        uses = ""


def main():
    files = [l.strip() for l in open(sys.argv[1]) if l.strip()]
    for i, name in enumerate(files):
        # Not reified: svgelements's reified arcs are wrong under a skew or an
        # uneven scale (it keeps the images of the axes' ends as if they were
        # still axes), so points are evaluated on each shape as written and
        # mapped by its transform (every group's, the element's, the use's
        # and the viewport's, composed by svgelements).
        svg = se.SVG.parse(name, reify=False, ppi=96)
        r = rounding(svg)
        with open(f"{sys.argv[2]}/{i}.ref", "w") as f:
            f.write(f"page {svg.height / r!r}\n")
            for ident, e in shapes(svg, ""):
                for n, (closed, segs) in enumerate(subpaths(e)):
                    name_n = ident if n == 0 else f"{ident}.{n + 1}"
                    m = e.transform
                    total = sum(length(s, m) for s in segs) / r
                    f.write(f"subpath {name_n} {'closed' if closed else 'open'} {total!r}\n")
                    pts = [segs[0].start]
                    for s in segs:
                        pts += [s.point(k / 8) for k in range(1, 9)]
                    pts = [m.point_in_matrix_space(p) for p in pts]
                    for p in pts:
                        f.write(f"{p.x / r!r} {p.y / r!r}\n")


main()
