%
(bezcam 0.1.0: curve-exercise-8.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009295 mm, proven bound 0.009914 mm, rounding included)
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
X0.393 Y0.033 F600.
X0.561 Y0.14
X0.576 Y0.299
X0.394 Y0.596
X-0.45 Y1.474
X-0.584 Y1.736
X-0.544 Y1.882
X-0.339 Y1.98
X0. Y2.
G00 Z5.
M05
M30
%
