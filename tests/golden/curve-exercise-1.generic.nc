%
(bezcam 0.1.0: curve-exercise-1.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009224 mm, proven bound 0.00955 mm, rounding included)
(T1: seed-ex-1)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.23 s; the exact path's bound on this machine 0.21 s [x1.068; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-1: bezier, degree 2, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.668 Y0.029 F600.
X1.097 Y0.139
X1.291 Y0.284
X1.342 Y0.462
X1.253 Y0.706
X1. Y1.
G00 Z5.
M05
M30
%
