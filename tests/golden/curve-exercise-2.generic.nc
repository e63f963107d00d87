%
(bezcam 0.1.0: curve-exercise-2.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009197 mm, proven bound 0.009659 mm, rounding included)
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
X0.553 Y-0.249 F600.
X0.953 Y-0.341
X1.183 Y-0.307
X1.307 Y-0.183
X1.341 Y0.047
X1.249 Y0.447
X1. Y1.
G00 Z5.
M05
M30
%
