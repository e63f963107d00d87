%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured 0.007981 mm, proven bound 0.008309 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity seed-ex-9: bezier, degree 4, 2D)
N70 G00 Z5.
N80 X0. Y-1.
N90 G01 Z-0.5 F200.
N100 (not exact: degree 4 reduced to 2 pieces of degree 3)
N110 G06.2 P4 K0. X0. Y-1. Z-0.5 R1. F600.
N120 K0. X0.653 Y0.305 Z-0.5 R1.
N130 K0. X0.344 Y0.25 Z-0.5 R1.
N140 K0. X0. Y0.25 Z-0.5 R1.
N150 K1. X-0.317 Y0.25 Z-0.5 R1.
N160 K1. X-0.688 Y0.312 Z-0.5 R1.
N170 K1. X0. Y1. Z-0.5 R1.
N180 K2.
N190 K2.
N200 K2.
N210 K2.
N220 G00 Z5.
N230 M05
N240 G00 Z5.
N250 M30
%
