%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-2.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009066 mm, proven bound 0.009412 mm, rounding included)
N30 (T1: seed-ex-2)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 0.31 s; the exact path's bound on this machine 0.26 s [x1.152; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity seed-ex-2: bezier, degree 2, 2D)
N140 G00 Z5.
N150 X0. Y0.
N160 G01 Z-0.5 F200.
N170 X0.559 Y-0.251 F600.
N180 X0.962 Y-0.341
N190 X1.186 Y-0.306
N200 X1.306 Y-0.186
N210 X1.341 Y0.038
N220 X1.251 Y0.441
N230 X1. Y1.
N240 G00 Z5.
N250 M05
N260 M30
%
