%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-1.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.0095 mm, proven bound 0.009975 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity seed-ex-1: bezier, degree 2, 2D)
N100 G00 Z5.
N110 X0. Y0.
N120 G01 Z-0.5 F200.
N130 X0.629 Y0.033 F600.
N140 X1.003 Y0.112
N150 X1.208 Y0.213
N160 X1.307 Y0.329
N170 X1.333 Y0.464
N180 X1.28 Y0.641
N190 X1.112 Y0.88
N200 X1. Y1.
N210 G00 Z5.
N220 M05
N230 M30
%
