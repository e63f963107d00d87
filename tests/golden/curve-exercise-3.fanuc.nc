%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-3.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009777 mm, proven bound 0.009933 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity seed-ex-3: bezier, degree 2, 2D)
N70 G00 Z5.
N80 X-1. Y0.
N90 G01 Z-0.5 F200.
N100 X-0.545 Y0.403 F600.
N110 X-0.119 Y0.687
N120 X0.286 Y0.872
N130 X0.675 Y0.974
N140 X1. Y1.
N150 G00 Z5.
N160 M05
N170 G00 Z5.
N180 M30
%
