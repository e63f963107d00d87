%
(bezcam 0.1.0: curve-exercise-5.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009112 mm, proven bound 0.009842 mm, rounding included)
(T1: seed-ex-5)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-5: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.53 Y0.491 F600.
X1.044 Y0.842
X1.417 Y0.996
X1.498 Y1.009
X1.465 Y0.995
X1.097 Y1.129
X0.562 Y1.483
X0. Y2.
G00 Z5.
M05
M30
%
