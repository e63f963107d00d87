%
(bezcam 0.1.0: curve-exercise-4.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009757 mm, proven bound 0.00998 mm, rounding included)
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
X0.346 Y0.038 F600.
X0.688 Y0.15
X0.953 Y0.305
X1.103 Y0.462
X1.154 Y0.599
X1.126 Y0.718
X1.013 Y0.827
X0.775 Y0.923
X0.365 Y0.987
X0. Y1.
G00 Z5.
M05
M30
%
