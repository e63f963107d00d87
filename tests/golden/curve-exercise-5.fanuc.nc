%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-5.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009112 mm, proven bound 0.009842 mm, rounding included)
N30 (T1: seed-ex-5)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-5: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.53 Y0.491 F600.
N170 X1.044 Y0.842
N180 X1.417 Y0.996
N190 X1.498 Y1.009
N200 X1.465 Y0.995
N210 X1.097 Y1.129
N220 X0.562 Y1.483
N230 X0. Y2.
N240 G00 Z5.
N250 M05
N260 M30
%
