%
(bezcam 0.1.0: curve-exercise-8.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009219 mm, proven bound 0.009649 mm, rounding included)
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
X0.359 Y0.024 F600.
X0.544 Y0.118
X0.584 Y0.261
X0.478 Y0.488
X0. Y1.
X-0.478 Y1.512
X-0.584 Y1.739
X-0.544 Y1.882
X-0.359 Y1.976
X0. Y2.
G00 Z5.
M05
M30
%
