%
(bezcam 0.1.0: curve-exercise-7.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009171 mm, proven bound 0.009675 mm, rounding included)
(T1: seed-ex-7)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-7: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.612 Y0.58 F600.
X1.021 Y0.864
X1.275 Y0.94
X1.506 Y0.882
X1.775 Y0.732
X2.09 Y0.694
X2.505 Y0.781
X3. Y1.
G00 Z5.
M05
M30
%
