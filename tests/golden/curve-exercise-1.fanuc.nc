%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-1.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009224 mm, proven bound 0.00955 mm, rounding included)
N30 (T1: seed-ex-1)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.26 s; the exact path's bound on this machine 0.21 s [x1.185; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-1: bezier, degree 2, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-0.5 F200.
N180 X0.668 Y0.029 F600.
N190 X1.097 Y0.139
N200 X1.291 Y0.284
N210 X1.342 Y0.462
N220 X1.253 Y0.706
N230 X1. Y1.
N240 G00 Z5.
N250 M05
N260 M30
%
