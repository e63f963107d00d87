%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-7.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009371 mm, proven bound 0.009967 mm, rounding included)
N30 (T1: seed-ex-7)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 (cutting along the curves 0.38 s; the exact path's bound on this machine 0.34 s [x1.118; rapids, plunges and pauses not counted])
N60 G21 G90 G17
N70 G40 G49 G80 G94
N80 G54
N90 G53 G00 Z0.
N100 T1 M06
N110 G43 H1
N120 S12000 M03
N130 (entity seed-ex-7: bezier, degree 3, 2D)
N140 G00 Z5.
N150 X0. Y0.
N160 G01 Z-0.5 F200.
N170 X0.663 Y0.621 F600.
N180 X1.082 Y0.893
N190 X1.34 Y0.938
N200 X1.574 Y0.836
N210 X1.821 Y0.719
N220 X2.116 Y0.695
N230 X2.519 Y0.785
N240 X3. Y1.
N250 G00 Z5.
N260 M05
N270 M30
%
