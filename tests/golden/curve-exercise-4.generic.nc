%
(bezcam 0.1.0: curve-exercise-4.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009322 mm, proven bound 0.009922 mm, rounding included)
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
X0.415 Y0.045 F600.
X0.859 Y0.229
X1.108 Y0.453
X1.162 Y0.642
X1.078 Y0.79
X0.824 Y0.918
X0.233 Y1.004
X0. Y1.
G00 Z5.
M05
M30
%
