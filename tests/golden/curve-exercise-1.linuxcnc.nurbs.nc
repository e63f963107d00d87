%
(bezcam 0.1.0: curve-exercise-1.json, machine linuxcnc, output nurbs)
(tolerance 0.01 mm; largest deviation measured 0 mm, proven bound 0 mm, rounding included)
(T1: seed-ex-1)
(T1 plunge feed 200 mm/min)
(estimated cycle time 2 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 0.25 s; the exact path's bound on this machine 0.21 s [x1.138; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T1 M6
G43 H1
S12000 M3
(entity seed-ex-1: bezier, degree 2, 2D)
G0 Z5.
X0. Y0.
G1 Z-0.5 F200.
G5.1 X1. Y1. I2. J0. F600.
G0 Z5.
M5
M30
%
