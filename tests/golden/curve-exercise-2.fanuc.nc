%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-2.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009066 mm, proven bound 0.009412 mm, rounding included)
N30 (T1: seed-ex-2)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.31 s; the exact path's bound on this machine 0.26 s [x1.152; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-2: bezier, degree 2, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-0.5 F200.
N180 X0.559 Y-0.251 F600.
N190 X0.962 Y-0.341
N200 X1.186 Y-0.306
N210 X1.306 Y-0.186
N220 X1.341 Y0.038
N230 X1.251 Y0.441
N240 X1. Y1.
N250 G00 Z5.
N260 M05
N270 M30
%
