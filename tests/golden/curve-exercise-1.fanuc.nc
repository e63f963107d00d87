%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-1.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.0095 mm, proven bound 0.009975 mm, rounding included)
N30 (T1: seed-ex-1)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-1: bezier, degree 2, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.629 Y0.033 F600.
N170 X1.003 Y0.112
N180 X1.208 Y0.213
N190 X1.307 Y0.329
N200 X1.333 Y0.464
N210 X1.28 Y0.641
N220 X1.112 Y0.88
N230 X1. Y1.
N240 G00 Z5.
N250 M05
N260 M30
%
