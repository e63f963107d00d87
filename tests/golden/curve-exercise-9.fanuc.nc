%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009385 mm, proven bound 0.009975 mm, rounding included)
N30 (T1: seed-ex-9)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-9: bezier, degree 4, 2D)
N130 G00 Z5.
N140 X0. Y-1.
N150 G01 Z-0.5 F200.
N160 X0.296 Y-0.343 F600.
N170 X0.381 Y-0.029
N180 X0.37 Y0.125
N190 X0.303 Y0.206
N200 X0.18 Y0.243
N210 X-0.253 Y0.269
N220 X-0.348 Y0.318
N230 X-0.385 Y0.405
N240 X-0.348 Y0.553
N250 X-0.186 Y0.797
N260 X0. Y1.
N270 G00 Z5.
N280 M05
N290 M30
%
