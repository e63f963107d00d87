%
(bezcam 0.1.0: curve-exercise-6.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009676 mm, proven bound 0.009987 mm, rounding included)
(T1: seed-ex-6)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-6: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.52 Y0.043 F600.
X0.983 Y0.21
X1.299 Y0.462
X1.473 Y0.768
X1.503 Y1.098
X1.389 Y1.416
X1.134 Y1.692
X0.735 Y1.898
X0.195 Y2.002
X0. Y2.
G00 Z5.
M05
M30
%
