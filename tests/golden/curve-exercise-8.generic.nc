%
(bezcam 0.1.0: curve-exercise-8.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009312 mm, proven bound 0.009847 mm, rounding included)
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
X0.581 Y0.279
X0.457 Y0.517
X-0.248 Y1.253
X-0.53 Y1.595
X-0.585 Y1.795
X-0.504 Y1.917
X-0.275 Y1.992
X0. Y2.
G00 Z5.
M05
M30
%
