%
(bezcam 0.1.0: curve-exercise-6.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009354 mm, proven bound 0.009403 mm, rounding included)
(T1: seed-ex-6)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.42 s; the exact path's bound on this machine 0.39 s [x1.040; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-6: bezier, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.484 Y0.035 F600.
X0.932 Y0.183
X1.252 Y0.411
X1.445 Y0.692
X1.509 Y1.
X1.445 Y1.308
X1.252 Y1.589
X0.932 Y1.817
X0.484 Y1.965
X0. Y2.
G00 Z5.
M05
M30
%
