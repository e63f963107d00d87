%
(bezcam 0.1.0: curve-exercise-4.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.00913 mm, proven bound 0.009541 mm, rounding included)
(T1: seed-ex-4)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.29 s; the exact path's bound on this machine 0.27 s [x1.059; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-4: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.372 Y0.035 F600.
X0.783 Y0.186
X1.057 Y0.389
X1.16 Y0.574
X1.129 Y0.731
X0.958 Y0.867
X0.575 Y0.972
X0. Y1.
G00 Z5.
M05
M30
%
