(bezcam 0.1.0: curve-semicircle.json, machine grbl, output nurbs)
(tolerance 0.005 mm; largest deviation measured 0.004879 mm, proven bound 0.004941 mm, rounding included)
(T1: semicircle-r3)
(T1 plunge feed 200 mm/min)
(estimated cycle time 6 s on the motion model of machine grbl [acceleration, corners, tool changes])
(cutting along the curves 0.74 s; the exact path's bound on this machine 0.71 s [x1.034; rapids, plunges and pauses not counted])
(machine grbl has no NURBS words: nurbs output cuts with arcs [G02/G03] and G01 lines)
G21 G90 G17
G40 G49 G80 G94
G54
(tool 1: load it before starting)
S12000 M3
G4 P2.
(entity semicircle-r3: bezier, degree 3, 2D)
G0 Z5.
X-3. Y0.
G1 Z-0.5 F200.
G2 X-2.372 Y1.925 I3.023 J0.079 F800.
G2 X-1.73 Y2.503 I1.9 J-1.465
G2 X1.926 Y2.364 I1.727 J-2.723
G2 X2.579 Y1.628 I-1.455 J-1.949
G2 X3. Y0. I-2.74 J-1.577
G0 Z5.
M5
M30
