# Writes the DXF drawings with text that tests/import/dxf_text_test.cpp and
# tests/cli/dxf_text_cli_test.cpp read, with ezdxf (python3-ezdxf):
#   /usr/bin/python3 tests/import/data/text/make_text_dxf.py tests/import/data/text
# Each text's handle is fixed, so that the tests can name it.
import sys

import ezdxf
from ezdxf.enums import TextEntityAlignment

out = sys.argv[1] if len(sys.argv) > 1 else "."


def new(units=4):
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = units
    doc.styles.new("SANS", dxfattribs={"font": "DejaVuSans.ttf"})
    return doc


def plate(msp):
    # A 130 x 70 plate round the texts: the drawing has curves too.
    msp.add_lwpolyline([(-10, -10), (130, -10), (130, 60), (-10, 60)], close=True, dxfattribs={"layer": "OUTLINE"})


def plated(style=None, font=None):
    # A drawing with the plate, and a text style `style` of `font` if given.
    doc = new()
    msp = doc.modelspace()
    plate(msp)
    if style:
        doc.styles.new(style, dxfattribs={"font": font})
    return doc, msp


# text.dxf: TEXT left on the baseline, rotated and centred in the middle,
# top right, bottom left, aligned between two points; MTEXT with inline
# formatting codes, turned 90 degrees, attached at its middle centre.
doc, msp = plated()
a = {"layer": "NOTES", "style": "SANS"}
msp.add_text("HELLO", height=5, dxfattribs=dict(a, insert=(10, 10)))
msp.add_text("HIH", height=4, rotation=30, dxfattribs=a).set_placement(
    (50, 20), align=TextEntityAlignment.MIDDLE_CENTER)
msp.add_text("HIT", height=3, dxfattribs=a).set_placement((100, 0), align=TextEntityAlignment.TOP_RIGHT)
msp.add_text("HIH", height=2, dxfattribs=a).set_placement((0, 30), align=TextEntityAlignment.BOTTOM_LEFT)
msp.add_text("HIH", dxfattribs=a).set_placement((0, 40), (60, 50), align=TextEntityAlignment.ALIGNED)
mt = msp.add_mtext("{\\fDejaVu Sans|b0|i0;M}\\H1.2x;TEXT\\~%%p0.1 \\S1/2;",
                   dxfattribs={"layer": "MARKS", "style": "SANS", "char_height": 3, "insert": (120, 30),
                               "attachment_point": 5, "rotation": 90})
doc.saveas(f"{out}/text.dxf")

# text-shx.dxf: a text in a style whose font is an SHX file.
doc, msp = plated("ROMANS", "romans.shx")
msp.add_text("PART 7", height=5, dxfattribs={"layer": "NOTES", "style": "ROMANS", "insert": (20, 25)})
doc.saveas(f"{out}/text-shx.dxf")

# text-missing-font.dxf: a style naming a TrueType font that is not
# installed (the stand-in is used, with a warning).
doc, msp = plated("GONE", "no-such-font-bezcam.ttf")
msp.add_text("HIH", height=5, dxfattribs={"layer": "NOTES", "style": "GONE", "insert": (20, 25)})
doc.saveas(f"{out}/text-missing-font.dxf")

# text-lines.dxf: an MTEXT of two lines (refused).
doc, msp = plated()
msp.add_mtext("FIRST\\PSECOND", dxfattribs={"layer": "NOTES", "style": "SANS", "char_height": 3,
                                            "insert": (10, 40)})
doc.saveas(f"{out}/text-lines.dxf")

# text-unitless.dxf: $INSUNITS 0, a 4 x 2 plate with a text 0.5 high (the
# drawing is in inches, which the file does not say).
doc = new(units=0)
msp = doc.modelspace()
msp.add_lwpolyline([(0, 0), (4, 0), (4, 2), (0, 2)], close=True, dxfattribs={"layer": "OUTLINE"})
msp.add_text("HIH", height=0.5, dxfattribs={"layer": "NOTES", "style": "SANS", "insert": (1, 1)})
doc.saveas(f"{out}/text-unitless.dxf")
