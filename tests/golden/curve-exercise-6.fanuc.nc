%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-6.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009354 mm, proven bound 0.009403 mm, rounding included)
N30 (T1: seed-ex-6)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-6: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.484 Y0.035 F600.
N170 X0.932 Y0.183
N180 X1.252 Y0.411
N190 X1.445 Y0.692
N200 X1.509 Y1.
N210 X1.445 Y1.308
N220 X1.252 Y1.589
N230 X0.932 Y1.817
N240 X0.484 Y1.965
N250 X0. Y2.
N260 G00 Z5.
N270 M05
N280 M30
%
