%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-7.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009491 mm, proven bound 0.009859 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity seed-ex-7: bezier, degree 3, 2D)
N70 G00 Z5.
N80 X0. Y0.
N90 G01 Z-0.5 F200.
N100 X0.617 Y0.573 F600.
N110 X0.973 Y0.828
N120 X1.2 Y0.922
N130 X1.371 Y0.923
N140 X1.597 Y0.823
N150 X1.844 Y0.722
N160 X2.091 Y0.703
N170 X2.42 Y0.763
N180 X2.872 Y0.938
N190 X3. Y1.
N200 G00 Z5.
N210 M05
N220 G00 Z5.
N230 M30
%
