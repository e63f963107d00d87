%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-8.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009219 mm, proven bound 0.009649 mm, rounding included)
N30 (T1: seed-ex-8)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-8: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.359 Y0.024 F600.
N170 X0.544 Y0.118
N180 X0.584 Y0.261
N190 X0.478 Y0.488
N200 X0. Y1.
N210 X-0.478 Y1.512
N220 X-0.584 Y1.739
N230 X-0.544 Y1.882
N240 X-0.359 Y1.976
N250 X0. Y2.
N260 G00 Z5.
N270 M05
N280 M30
%
