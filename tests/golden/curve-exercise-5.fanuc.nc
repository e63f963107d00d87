%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-5.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009761 mm, proven bound 0.009926 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity seed-ex-5: bezier, degree 3, 2D)
N100 G00 Z5.
N110 X0. Y0.
N120 G01 Z-0.5 F200.
N130 X0.531 Y0.481 F600.
N140 X0.97 Y0.79
N150 X1.312 Y0.955
N160 X1.491 Y1.
N170 X1.236 Y1.074
N180 X0.86 Y1.279
N190 X0.396 Y1.632
N200 X0. Y2.
N210 G00 Z5.
N220 M05
N230 M30
%
