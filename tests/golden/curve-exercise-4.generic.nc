%
(bezcam 0.1.0: curve-exercise-4.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.00928 mm, proven bound 0.00973 mm, rounding included)
(T1: seed-ex-4)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-4: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.371 Y0.034 F600.
X0.779 Y0.184
X1.05 Y0.381
X1.159 Y0.568
X1.128 Y0.732
X0.956 Y0.868
X0.573 Y0.973
X0. Y1.
G00 Z5.
M05
M30
%
