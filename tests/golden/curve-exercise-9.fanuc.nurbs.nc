%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured 0.007981 mm, proven bound 0.008309 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity seed-ex-9: bezier, degree 4, 2D)
N100 G00 Z5.
N110 X0. Y-1.
N120 G01 Z-0.5 F200.
N130 (not exact: degree 4 reduced to 2 pieces of degree 3)
N140 G06.2 P4 K0. X0. Y-1. Z-0.5 R1. F600.
N150 K0. X0.653 Y0.305 Z-0.5 R1.
N160 K0. X0.344 Y0.25 Z-0.5 R1.
N170 K0. X0. Y0.25 Z-0.5 R1.
N180 K1. X-0.317 Y0.25 Z-0.5 R1.
N190 K1. X-0.688 Y0.312 Z-0.5 R1.
N200 K1. X0. Y1. Z-0.5 R1.
N210 K2.
N220 K2.
N230 K2.
N240 K2.
N250 G00 Z5.
N260 M05
N270 M30
%
