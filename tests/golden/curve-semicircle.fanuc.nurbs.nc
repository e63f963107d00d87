%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output nurbs)
N20 (tolerance 0.005 mm; largest deviation measured below 5e-06 mm, proven bound 2.22e-16 mm, rounding included)
N30 G21 G90 G17
N40 G40 G49 G80 G94
N50 G54
N60 T1 M06
N70 G43 H1
N80 S12000 M03
N90 (entity semicircle-r3: bezier, degree 3, 2D)
N100 G00 Z5.
N110 X-3. Y0.
N120 G01 Z-0.5 F200.
N130 G06.2 P4 K0. X-3. Y0. Z-0.5 R1. F800.
N140 K0. X-3. Y4. Z-0.5 R1.
N150 K0. X3. Y4. Z-0.5 R1.
N160 K0. X3. Y0. Z-0.5 R1.
N170 K1.
N180 K1.
N190 K1.
N200 K1.
N210 G00 Z5.
N220 M05
N230 M30
%
