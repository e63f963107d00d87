%
(bezcam 0.1.0: curve-exercise-6.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009204 mm, proven bound 0.009779 mm, rounding included)
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
X0.511 Y0.041 F600.
X0.972 Y0.204
X1.291 Y0.453
X1.469 Y0.756
X1.504 Y1.083
X1.397 Y1.402
X1.148 Y1.681
X0.757 Y1.891
X0.225 Y2.
X0.
G00 Z5.
M05
M30
%
