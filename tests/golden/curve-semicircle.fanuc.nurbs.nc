%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output nurbs)
N20 (tolerance 0.005 mm; largest deviation measured below 2.22e-16 mm, proven bound 2.221e-16 mm, rounding included)
N30 (T1: semicircle-r3)
N40 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N50 G21 G90 G17
N60 G40 G49 G80 G94
N70 G54
N80 G53 G00 Z0.
N90 T1 M06
N100 G43 H1
N110 S12000 M03
N120 (entity semicircle-r3: bezier, degree 3, 2D)
N130 G00 Z5.
N140 X-3. Y0.
N150 G01 Z-0.5 F200.
N160 G06.2 P4 K0. X-3. Y0. Z-0.5 R1. F800.
N170 K0. X-3. Y4. Z-0.5 R1.
N180 K0. X3. Y4. Z-0.5 R1.
N190 K0. X3. Y0. Z-0.5 R1.
N200 K1.
N210 K1.
N220 K1.
N230 K1.
N240 G00 Z5.
N250 M05
N260 M30
%
