%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-2.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009066 mm, proven bound 0.009412 mm, rounding included)
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
N160 X0.559 Y-0.251 F600.
N170 X0.962 Y-0.341
N180 X1.186 Y-0.306
N190 X1.306 Y-0.186
N200 X1.341 Y0.038
N210 X1.251 Y0.441
N220 X1. Y1.
N230 G00 Z5.
N240 M05
N250 M30
%
