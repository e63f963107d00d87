%
(bezcam 0.1.0: curve-exercise-8.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009723 mm, proven bound 0.009995 mm, rounding included)
(T1: seed-ex-8)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-8: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.401 Y0.036 F600.
X0.564 Y0.146
X0.573 Y0.308
X0.36 Y0.637
X-0.44 Y1.461
X-0.584 Y1.736
X-0.544 Y1.883
X-0.33 Y1.982
X0. Y2.
G00 Z5.
M05
M30
%
