%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-7.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009491 mm, proven bound 0.009859 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity seed-ex-7: bezier, degree 3, 2D)
N100 G00 Z5.
N110 X0. Y0.
N120 G01 Z-0.5 F200.
N130 X0.617 Y0.573 F600.
N140 X0.973 Y0.828
N150 X1.2 Y0.922
N160 X1.371 Y0.923
N170 X1.597 Y0.823
N180 X1.844 Y0.722
N190 X2.091 Y0.703
N200 X2.42 Y0.763
N210 X2.872 Y0.938
N220 X3. Y1.
N230 G00 Z5.
N240 M05
N250 M30
%
