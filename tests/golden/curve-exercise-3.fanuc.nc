%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-3.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009777 mm, proven bound 0.009933 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity seed-ex-3: bezier, degree 2, 2D)
N100 G00 Z5.
N110 X-1. Y0.
N120 G01 Z-0.5 F200.
N130 X-0.545 Y0.403 F600.
N140 X-0.119 Y0.687
N150 X0.286 Y0.872
N160 X0.675 Y0.974
N170 X1. Y1.
N180 G00 Z5.
N190 M05
N200 M30
%
