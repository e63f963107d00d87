%
(bezcam 0.1.0: curve-exercise-1.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.0095 mm, proven bound 0.009975 mm, rounding included)
(T1: seed-ex-1)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-1: bezier, degree 2, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.629 Y0.033 F600.
X1.003 Y0.112
X1.208 Y0.213
X1.307 Y0.329
X1.333 Y0.464
X1.28 Y0.641
X1.112 Y0.88
X1. Y1.
G00 Z5.
M05
M30
%
