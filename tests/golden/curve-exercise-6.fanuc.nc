%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-6.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009354 mm, proven bound 0.009403 mm, rounding included)
N30 (T1: seed-ex-6)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.44 s; the exact path's bound on this machine 0.39 s [x1.102; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-6: bezier, degree 3, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-0.5 F200.
N180 X0.484 Y0.035 F600.
N190 X0.932 Y0.183
N200 X1.252 Y0.411
N210 X1.445 Y0.692
N220 X1.509 Y1.
N230 X1.445 Y1.308
N240 X1.252 Y1.589
N250 X0.932 Y1.817
N260 X0.484 Y1.965
N270 X0. Y2.
N280 G00 Z5.
N290 M05
N300 M30
%
