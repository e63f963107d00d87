%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-5.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009438 mm, proven bound 0.009491 mm, rounding included)
N30 (T1: seed-ex-5)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.45 s; the exact path's bound on this machine 0.36 s [x1.207; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-5: bezier, degree 3, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-0.5 F200.
N180 X0.482 Y0.453 F600.
N190 X0.96 Y0.795
N200 X1.332 Y0.972
N210 X1.5 Y1.
N220 X1.332 Y1.028
N230 X0.96 Y1.205
N240 X0.482 Y1.547
N250 X0. Y2.
N260 G00 Z5.
N270 M05
N280 M30
%
