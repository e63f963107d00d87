%
(bezcam 0.1.0: curve-exercise-2.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009558 mm, proven bound 0.00989 mm, rounding included)
(T1: seed-ex-2)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-2: bezier, degree 2, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.553 Y-0.24 F600.
X0.898 Y-0.326
X1.112 Y-0.322
X1.241 Y-0.258
X1.314 Y-0.141
X1.331 Y0.054
X1.265 Y0.371
X1.064 Y0.868
X1. Y1.
G00 Z5.
M05
M30
%
