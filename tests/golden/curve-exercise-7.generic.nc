%
(bezcam 0.1.0: curve-exercise-7.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009613 mm, proven bound 0.009969 mm, rounding included)
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
X0.708 Y0.657 F600.
X1.119 Y0.907
X1.37 Y0.933
X1.841 Y0.714
X2.204 Y0.706
X2.748 Y0.873
X3. Y1.
G00 Z5.
M05
M30
%
