%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-5.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009761 mm, proven bound 0.009926 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity seed-ex-5: bezier, degree 3, 2D)
N70 G00 Z5.
N80 X0. Y0.
N90 G01 Z-0.5 F200.
N100 X0.531 Y0.481 F600.
N110 X0.97 Y0.79
N120 X1.312 Y0.955
N130 X1.491 Y1.
N140 X1.236 Y1.074
N150 X0.86 Y1.279
N160 X0.396 Y1.632
N170 X0. Y2.
N180 G00 Z5.
N190 M05
N200 G00 Z5.
N210 M30
%
