%
(bezcam 0.1.0: curve-semicircle.json, machine generic, output arcs)
(tolerance 0.005 mm; largest deviation measured 0.004879 mm, proven bound 0.004941 mm, rounding included)
(T1: semicircle-r3)
(T1 plunge feed 200 mm/min)
(estimated cycle time 10 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.72 s; the exact path's bound on this machine 0.71 s [x1.015; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity semicircle-r3: bezier, degree 3, 2D)
G00 Z5.
X-3. Y0.
G01 Z-0.5 F200.
G02 X-2.372 Y1.925 I3.023 J0.079 F800.
G02 X-1.73 Y2.503 I1.9 J-1.465
G02 X1.926 Y2.364 I1.727 J-2.723
G02 X2.579 Y1.628 I-1.455 J-1.949
G02 X3. Y0. I-2.74 J-1.577
G00 Z5.
M05
M30
%
