%
(bezcam 0.1.0: curve-exercise-2.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009432 mm, proven bound 0.00996 mm, rounding included)
(T1: seed-ex-2)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-2: bezier, degree 2, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.627 Y-0.274 F600.
X1.035 Y-0.341
X1.239 Y-0.272
X1.335 Y-0.094
X1.304 Y0.267
X1.032 Y0.955
X1. Y1.
G00 Z5.
M05
M30
%
