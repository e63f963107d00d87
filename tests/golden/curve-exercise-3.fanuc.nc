%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-3.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.0094 mm, proven bound 0.009554 mm, rounding included)
N30 (T1: seed-ex-3)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-3: bezier, degree 2, 2D)
N130 G00 Z5.
N140 X-1. Y0.
N150 G01 Z-0.5 F200.
N160 X-0.507 Y0.444 F600.
N170 X0.042 Y0.78
N180 X0.564 Y0.962
N190 X1. Y1.
N200 G00 Z5.
N210 M05
N220 M30
%
