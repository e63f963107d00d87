%
(bezcam 0.1.0: curve-exercise-7.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009285 mm, proven bound 0.009754 mm, rounding included)
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
X0.693 Y0.646 F600.
X1.111 Y0.904
X1.353 Y0.936
X1.575 Y0.845
X1.779 Y0.731
X2.116 Y0.695
X2.556 Y0.798
X3. Y1.
G00 Z5.
M05
M30
%
