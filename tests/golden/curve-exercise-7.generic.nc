%
(bezcam 0.1.0: curve-exercise-7.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009051 mm, proven bound 0.009569 mm, rounding included)
(T1: seed-ex-7)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-7: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.614 Y0.582 F600.
X1.023 Y0.865
X1.273 Y0.94
X1.493 Y0.888
X1.791 Y0.727
X2.094 Y0.694
X2.504 Y0.78
X3. Y1.
G00 Z5.
M05
M30
%
