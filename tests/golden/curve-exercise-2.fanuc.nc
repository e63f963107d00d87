%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-2.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009558 mm, proven bound 0.00989 mm, rounding included)
N30 (T1: seed-ex-2)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-2: bezier, degree 2, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.553 Y-0.24 F600.
N170 X0.898 Y-0.326
N180 X1.112 Y-0.322
N190 X1.241 Y-0.258
N200 X1.314 Y-0.141
N210 X1.331 Y0.054
N220 X1.265 Y0.371
N230 X1.064 Y0.868
N240 X1. Y1.
N250 G00 Z5.
N260 M05
N270 M30
%
