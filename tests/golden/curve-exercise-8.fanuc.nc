%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-8.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009338 mm, proven bound 0.009745 mm, rounding included)
N30 (T1: seed-ex-8)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.37 s; the exact path's bound on this machine 0.33 s [x1.118; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-8: bezier, degree 3, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-0.5 F200.
N180 X0.366 Y0.026 F600.
N190 X0.55 Y0.124
N200 X0.582 Y0.275
N210 X0.448 Y0.529
N220 X0. Y1.
N230 X-0.448 Y1.471
N240 X-0.582 Y1.725
N250 X-0.55 Y1.876
N260 X-0.366 Y1.974
N270 X0. Y2.
N280 G00 Z5.
N290 M05
N300 M30
%
