%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output nurbs)
N20 (tolerance 0.005 mm; largest deviation measured below 2.22e-16 mm, proven bound 2.221e-16 mm, rounding included)
N30 (T1: semicircle-r3)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.75 s; the exact path's bound on this machine 0.71 s [x1.049; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity semicircle-r3: bezier, degree 3, 2D)
N150 G00 Z5.
N160 X-3. Y0.
N170 G01 Z-0.5 F200.
N180 G06.2 P4 K0. X-3. Y0. Z-0.5 R1. F800.
N190 K0. X-3. Y4. Z-0.5 R1.
N200 K0. X3. Y4. Z-0.5 R1.
N210 K0. X3. Y0. Z-0.5 R1.
N220 K1.
N230 K1.
N240 K1.
N250 K1.
N260 G00 Z5.
N270 M05
N280 M30
%
