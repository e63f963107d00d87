%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output nurbs)
N20 (tolerance 0.01 mm; largest deviation measured 0.00798 mm, proven bound 0.00831 mm, rounding included)
N30 (T1: seed-ex-9)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.31 s; the exact path's bound on this machine 0.28 s [x1.101; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-9: bezier, degree 4, 2D)
N150 G00 Z5.
N160 X0. Y-1.
N170 G01 Z-0.5 F200.
N180 (not exact: degree 4 reduced to 2 pieces of degree 3)
N190 G06.2 P4 K0. X0. Y-1. Z-0.5 R1. F600.
N200 K0. X0.653 Y0.305 Z-0.5 R1.
N210 K0. X0.344 Y0.25 Z-0.5 R1.
N220 K0. X0. Y0.25 Z-0.5 R1.
N230 K1. X-0.317 Y0.25 Z-0.5 R1.
N240 K1. X-0.688 Y0.312 Z-0.5 R1.
N250 K1. X0. Y1. Z-0.5 R1.
N260 K2.
N270 K2.
N280 K2.
N290 K2.
N300 G00 Z5.
N310 M05
N320 M30
%
