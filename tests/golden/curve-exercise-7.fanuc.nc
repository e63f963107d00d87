%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-7.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009491 mm, proven bound 0.009859 mm, rounding included)
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
N160 X0.617 Y0.573 F600.
N170 X0.973 Y0.828
N180 X1.2 Y0.922
N190 X1.371 Y0.923
N200 X1.597 Y0.823
N210 X1.844 Y0.722
N220 X2.091 Y0.703
N230 X2.42 Y0.763
N240 X2.872 Y0.938
N250 X3. Y1.
N260 G00 Z5.
N270 M05
N280 M30
%
