%
(bezcam 0.1.0: curve-exercise-6.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009479 mm, proven bound 0.009916 mm, rounding included)
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
X0.44 Y0.036 F600.
X0.801 Y0.135
X1.085 Y0.284
X1.296 Y0.471
X1.432 Y0.685
X1.495 Y0.915
X1.485 Y1.149
X1.401 Y1.376
X1.244 Y1.585
X1.012 Y1.763
X0.706 Y1.899
X0.326 Y1.981
X0. Y2.
G00 Z5.
M05
M30
%
