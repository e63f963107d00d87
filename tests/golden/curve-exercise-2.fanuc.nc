%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-2.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009558 mm, proven bound 0.00989 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity seed-ex-2: bezier, degree 2, 2D)
N70 G00 Z5.
N80 X0. Y0.
N90 G01 Z-0.5 F200.
N100 X0.553 Y-0.24 F600.
N110 X0.898 Y-0.326
N120 X1.112 Y-0.322
N130 X1.241 Y-0.258
N140 X1.314 Y-0.141
N150 X1.331 Y0.054
N160 X1.265 Y0.371
N170 X1.064 Y0.868
N180 X1. Y1.
N190 G00 Z5.
N200 M05
N210 G00 Z5.
N220 M30
%
