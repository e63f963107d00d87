%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-8.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009543 mm, proven bound 0.009955 mm, rounding included)
N30 (T1: seed-ex-8)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-8: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.349 Y0.031 F600.
N170 X0.511 Y0.099
N180 X0.572 Y0.189
N190 X0.562 Y0.314
N200 X0.442 Y0.522
N210 X0.056 Y0.944
N220 X-0.414 Y1.442
N230 X-0.555 Y1.667
N240 X-0.575 Y1.801
N250 X-0.521 Y1.893
N260 X-0.373 Y1.963
N270 X-0.056 Y1.999
N280 X0. Y2.
N290 G00 Z5.
N300 M05
N310 M30
%
