%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-6.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009354 mm, proven bound 0.009403 mm, rounding included)
N30 (T1: seed-ex-6)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 0.44 s; the exact path's bound on this machine 0.39 s [x1.102; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity seed-ex-6: bezier, degree 3, 2D)
N140 G00 Z5.
N150 X0. Y0.
N160 G01 Z-0.5 F200.
N170 X0.484 Y0.035 F600.
N180 X0.932 Y0.183
N190 X1.252 Y0.411
N200 X1.445 Y0.692
N210 X1.509 Y1.
N220 X1.445 Y1.308
N230 X1.252 Y1.589
N240 X0.932 Y1.817
N250 X0.484 Y1.965
N260 X0. Y2.
N270 G00 Z5.
N280 M05
N290 M30
%
