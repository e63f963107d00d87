%
(bezcam 0.1.0: curve-exercise-5.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009302 mm, proven bound 0.009535 mm, rounding included)
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
X0.537 Y0.497 F600.
X1.055 Y0.849
X1.427 Y0.998
X1.499 Y1.009
X1.464 Y0.995
X1.096 Y1.13
X0.562 Y1.483
X0. Y2.
G00 Z5.
M05
M30
%
