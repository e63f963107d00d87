%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-7.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009371 mm, proven bound 0.009967 mm, rounding included)
N30 (T1: seed-ex-7)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-7: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.663 Y0.621 F600.
N170 X1.082 Y0.893
N180 X1.34 Y0.938
N190 X1.574 Y0.836
N200 X1.821 Y0.719
N210 X2.116 Y0.695
N220 X2.519 Y0.785
N230 X3. Y1.
N240 G00 Z5.
N250 M05
N260 M30
%
