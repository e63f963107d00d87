%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-9.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009385 mm, proven bound 0.009975 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity seed-ex-9: bezier, degree 4, 2D)
N70 G00 Z5.
N80 X0. Y-1.
N90 G01 Z-0.5 F200.
N100 X0.296 Y-0.343 F600.
N110 X0.381 Y-0.029
N120 X0.37 Y0.125
N130 X0.303 Y0.206
N140 X0.18 Y0.243
N150 X-0.253 Y0.269
N160 X-0.348 Y0.318
N170 X-0.385 Y0.405
N180 X-0.348 Y0.553
N190 X-0.186 Y0.797
N200 X0. Y1.
N210 G00 Z5.
N220 M05
N230 G00 Z5.
N240 M30
%
