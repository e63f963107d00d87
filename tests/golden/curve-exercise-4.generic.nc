%
(bezcam 0.1.0: curve-exercise-4.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009627 mm, proven bound 0.009967 mm, rounding included)
(T1: seed-ex-4)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-4: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.413 Y0.044 F600.
X0.862 Y0.231
X1.111 Y0.458
X1.161 Y0.649
X1.061 Y0.804
X0.749 Y0.939
X0.077 Y1.008
X0. Y1.
G00 Z5.
M05
M30
%
