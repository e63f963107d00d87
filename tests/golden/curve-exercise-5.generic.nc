%
(bezcam 0.1.0: curve-exercise-5.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009302 mm, proven bound 0.009946 mm, rounding included)
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
X0.616 Y0.559 F600.
X1.164 Y0.904
X1.499 Y1.009
X1.393 Y1.01
X0.939 Y1.218
X0.326 Y1.68
X0. Y2.
G00 Z5.
M05
M30
%
