%
(bezcam 0.1.0: curve-exercise-5.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009761 mm, proven bound 0.009926 mm, rounding included)
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
X0.531 Y0.481 F600.
X0.97 Y0.79
X1.312 Y0.955
X1.491 Y1.
X1.236 Y1.074
X0.86 Y1.279
X0.396 Y1.632
X0. Y2.
G00 Z5.
M05
M30
%
