%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-1.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009224 mm, proven bound 0.00955 mm, rounding included)
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
N160 X0.668 Y0.029 F600.
N170 X1.097 Y0.139
N180 X1.291 Y0.284
N190 X1.342 Y0.462
N200 X1.253 Y0.706
N210 X1. Y1.
N220 G00 Z5.
N230 M05
N240 M30
%
