%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-7.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009051 mm, proven bound 0.009569 mm, rounding included)
N30 (T1: seed-ex-7)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-7: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.614 Y0.582 F600.
N170 X1.023 Y0.865
N180 X1.273 Y0.94
N190 X1.493 Y0.888
N200 X1.791 Y0.727
N210 X2.094 Y0.694
N220 X2.504 Y0.78
N230 X3. Y1.
N240 G00 Z5.
N250 M05
N260 M30
%
