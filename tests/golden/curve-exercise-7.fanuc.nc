%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-7.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009371 mm, proven bound 0.009979 mm, rounding included)
N30 (T1: seed-ex-7)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.38 s; the exact path's bound on this machine 0.34 s [x1.118; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity seed-ex-7: bezier, degree 3, 2D)
N150 G00 Z5.
N160 X0. Y0.
N170 G01 Z-0.5 F200.
N180 X0.662 Y0.621 F600.
N190 X1.082 Y0.893
N200 X1.34 Y0.938
N210 X1.574 Y0.836
N220 X1.821 Y0.719
N230 X2.116 Y0.695
N240 X2.519 Y0.785
N250 X3. Y1.
N260 G00 Z5.
N270 M05
N280 M30
%
