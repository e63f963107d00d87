%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-2.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009558 mm, proven bound 0.00989 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity seed-ex-2: bezier, degree 2, 2D)
N100 G00 Z5.
N110 X0. Y0.
N120 G01 Z-0.5 F200.
N130 X0.553 Y-0.24 F600.
N140 X0.898 Y-0.326
N150 X1.112 Y-0.322
N160 X1.241 Y-0.258
N170 X1.314 Y-0.141
N180 X1.331 Y0.054
N190 X1.265 Y0.371
N200 X1.064 Y0.868
N210 X1. Y1.
N220 G00 Z5.
N230 M05
N240 M30
%
