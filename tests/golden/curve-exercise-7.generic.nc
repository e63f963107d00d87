%
(bezcam 0.1.0: curve-exercise-7.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009491 mm, proven bound 0.009859 mm, rounding included)
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
X0.617 Y0.573 F600.
X0.973 Y0.828
X1.2 Y0.922
X1.371 Y0.923
X1.597 Y0.823
X1.844 Y0.722
X2.091 Y0.703
X2.42 Y0.763
X2.872 Y0.938
X3. Y1.
G00 Z5.
M05
M30
%
