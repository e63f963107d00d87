%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-1.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009224 mm, proven bound 0.00955 mm, rounding included)
N30 (T1: seed-ex-1)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 0.26 s; the exact path's bound on this machine 0.21 s [x1.185; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity seed-ex-1: bezier, degree 2, 2D)
N140 G00 Z5.
N150 X0. Y0.
N160 G01 Z-0.5 F200.
N170 X0.668 Y0.029 F600.
N180 X1.097 Y0.139
N190 X1.291 Y0.284
N200 X1.342 Y0.462
N210 X1.253 Y0.706
N220 X1. Y1.
N230 G00 Z5.
N240 M05
N250 M30
%
