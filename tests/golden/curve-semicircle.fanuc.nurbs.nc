%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output nurbs)
N20 (tolerance 0.005 mm; largest deviation measured below 5e-06 mm, proven bound 2.22e-16 mm, rounding included)
N30 G21 G90 G17
N40 T1 M06
N50 S12000 M03
N60 (entity semicircle-r3: bezier, degree 3, 2D)
N70 G00 Z5.
N80 X-3. Y0.
N90 G01 Z-0.5 F200.
N100 G06.2 P4 K0. X-3. Y0. Z-0.5 R1. F800.
N110 K0. X-3. Y4. Z-0.5 R1.
N120 K0. X3. Y4. Z-0.5 R1.
N130 K0. X3. Y0. Z-0.5 R1.
N140 K1.
N150 K1.
N160 K1.
N170 K1.
N180 G00 Z5.
N190 M05
N200 G00 Z5.
N210 M30
%
