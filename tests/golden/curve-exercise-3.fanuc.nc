%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-3.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.0094 mm, proven bound 0.009554 mm, rounding included)
N30 (T1: seed-ex-3)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 0.27 s; the exact path's bound on this machine 0.22 s [x1.175; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity seed-ex-3: bezier, degree 2, 2D)
N140 G00 Z5.
N150 X-1. Y0.
N160 G01 Z-0.5 F200.
N170 X-0.507 Y0.444 F600.
N180 X0.042 Y0.78
N190 X0.564 Y0.962
N200 X1. Y1.
N210 G00 Z5.
N220 M05
N230 M30
%
