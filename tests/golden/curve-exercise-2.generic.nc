%
(bezcam 0.1.0: curve-exercise-2.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009403 mm, proven bound 0.009992 mm, rounding included)
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
X0.629 Y-0.274 F600.
X1.034 Y-0.341
X1.241 Y-0.271
X1.331 Y-0.114
X1.323 Y0.18
X1.111 Y0.788
X1. Y1.
G00 Z5.
M05
M30
%
