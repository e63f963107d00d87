%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009643 mm, proven bound 0.009992 mm, rounding included)
N30 (T1: seed-ex-9)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-9: bezier, degree 4, 2D)
N130 G00 Z5.
N140 X0. Y-1.
N150 G01 Z-0.5 F200.
N160 X0.34 Y-0.244 F600.
N170 X0.39 Y0.084
N180 X0.305 Y0.215
N190 X0.01 Y0.259
N200 X-0.261 Y0.262
N210 X-0.382 Y0.353
N220 X-0.366 Y0.535
N230 X-0.104 Y0.905
N240 X0. Y1.
N250 G00 Z5.
N260 M05
N270 M30
%
