%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-4.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009757 mm, proven bound 0.00998 mm, rounding included)
N30 (T1: seed-ex-4)
N40 (estimated cycle time 7 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity seed-ex-4: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X0. Y0.
N150 G01 Z-0.5 F200.
N160 X0.346 Y0.038 F600.
N170 X0.688 Y0.15
N180 X0.953 Y0.305
N190 X1.103 Y0.462
N200 X1.154 Y0.599
N210 X1.126 Y0.718
N220 X1.013 Y0.827
N230 X0.775 Y0.923
N240 X0.365 Y0.987
N250 X0. Y1.
N260 G00 Z5.
N270 M05
N280 M30
%
