%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-3.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.0094 mm, proven bound 0.009554 mm, rounding included)
N30 (T1: seed-ex-3)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.27 s; the exact path's bound on this machine 0.22 s [x1.175; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-3: bezier, degree 2, 2D)
N150 G00 Z5.
N160 X-1. Y0.
N170 G01 Z-0.5 F200.
N180 X-0.507 Y0.444 F600.
N190 X0.042 Y0.78
N200 X0.564 Y0.962
N210 X1. Y1.
N220 G00 Z5.
N230 M05
N240 M30
%
