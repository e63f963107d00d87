%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-exercise-4.json, machine fanuc, output lines)
N20 (tolerance 0.01 mm; largest deviation measured 0.009757 mm, proven bound 0.00998 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity seed-ex-4: bezier, degree 3, 2D)
N70 G00 Z5.
N80 X0. Y0.
N90 G01 Z-0.5 F200.
N100 X0.346 Y0.038 F600.
N110 X0.688 Y0.15
N120 X0.953 Y0.305
N130 X1.103 Y0.462
N140 X1.154 Y0.599
N150 X1.126 Y0.718
N160 X1.013 Y0.827
N170 X0.775 Y0.923
N180 X0.365 Y0.987
N190 X0. Y1.
N200 G00 Z5.
N210 M05
N220 G00 Z5.
N230 M30
%
