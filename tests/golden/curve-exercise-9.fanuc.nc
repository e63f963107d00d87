%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009643 mm, proven bound 0.009992 mm, rounding included)
N30 (T1: seed-ex-9)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 0.33 s; the exact path's bound on this machine 0.28 s [x1.168; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity seed-ex-9: bezier, degree 4, 2D)
N140 G00 Z5.
N150 X0. Y-1.
N160 G01 Z-0.5 F200.
N170 X0.34 Y-0.244 F600.
N180 X0.39 Y0.084
N190 X0.305 Y0.215
N200 X0.01 Y0.259
N210 X-0.261 Y0.262
N220 X-0.382 Y0.353
N230 X-0.366 Y0.535
N240 X-0.104 Y0.905
N250 X0. Y1.
N260 G00 Z5.
N270 M05
N280 M30
%
