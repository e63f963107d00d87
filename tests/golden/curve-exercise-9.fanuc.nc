%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009643 mm, proven bound 0.009992 mm, rounding included)
N30 (T1: seed-ex-9)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.33 s; the exact path's bound on this machine 0.28 s [x1.168; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-9: bezier, degree 4, 2D)
N150 G00 Z5.
N160 X0. Y-1.
N170 G01 Z-0.5 F200.
N180 X0.34 Y-0.244 F600.
N190 X0.39 Y0.084
N200 X0.305 Y0.215
N210 X0.01 Y0.259
N220 X-0.261 Y0.262
N230 X-0.382 Y0.353
N240 X-0.366 Y0.535
N250 X-0.104 Y0.905
N260 X0. Y1.
N270 G00 Z5.
N280 M05
N290 M30
%
