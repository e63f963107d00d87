%
(bezcam 0.1.0: curve-exercise-9.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009385 mm, proven bound 0.009975 mm, rounding included)
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
X0.296 Y-0.343 F600.
X0.381 Y-0.029
X0.37 Y0.125
X0.303 Y0.206
X0.18 Y0.243
X-0.253 Y0.269
X-0.348 Y0.318
X-0.385 Y0.405
X-0.348 Y0.553
X-0.186 Y0.797
X0. Y1.
G00 Z5.
M05
M30
%
