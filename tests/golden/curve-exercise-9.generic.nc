%
(bezcam 0.1.0: curve-exercise-9.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009557 mm, proven bound 0.009991 mm, rounding included)
(T1: seed-ex-9)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-9: bezier, degree 4, 2D)
G00 Z5.
X0. Y-1.
G01 Z-0.5 F200.
X0.34 Y-0.244 F600.
X0.39 Y0.082
X0.308 Y0.213
X0.029 Y0.259
X-0.259 Y0.261
X-0.381 Y0.351
X-0.368 Y0.53
X-0.113 Y0.895
X0. Y1.
G00 Z5.
M05
M30
%
