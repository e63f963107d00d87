%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-6.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009479 mm, proven bound 0.009916 mm, rounding included)
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
N160 X0.44 Y0.036 F600.
N170 X0.801 Y0.135
N180 X1.085 Y0.284
N190 X1.296 Y0.471
N200 X1.432 Y0.685
N210 X1.495 Y0.915
N220 X1.485 Y1.149
N230 X1.401 Y1.376
N240 X1.244 Y1.585
N250 X1.012 Y1.763
N260 X0.706 Y1.899
N270 X0.326 Y1.981
N280 X0. Y2.
N290 G00 Z5.
N300 M05
N310 M30
%
