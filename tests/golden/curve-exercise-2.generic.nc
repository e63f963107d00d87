%
(bezcam 0.1.0: curve-exercise-2.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009066 mm, proven bound 0.009412 mm, rounding included)
(T1: seed-ex-2)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.28 s; the exact path's bound on this machine 0.26 s [x1.058; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-2: bezier, degree 2, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.559 Y-0.251 F600.
X0.962 Y-0.341
X1.186 Y-0.306
X1.306 Y-0.186
X1.341 Y0.038
X1.251 Y0.441
X1. Y1.
G00 Z5.
M05
M30
%
