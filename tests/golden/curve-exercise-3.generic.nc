%
(bezcam 0.1.0: curve-exercise-3.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.0094 mm, proven bound 0.009554 mm, rounding included)
(T1: seed-ex-3)
(T1 plunge feed 200 mm/min)
(estimated cycle time 9 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 0.25 s; the exact path's bound on this machine 0.22 s [x1.070; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-3: bezier, degree 2, 2D)
G00 Z5.
X-1. Y0.
G01 Z-0.5 F200.
X-0.507 Y0.444 F600.
X0.042 Y0.78
X0.564 Y0.962
X1. Y1.
G00 Z5.
M05
M30
%
