%
(bezcam 0.1.0: curve-exercise-1.json, machine linuxcnc, output nurbs)
(tolerance 0.01 mm; largest deviation measured 0.009574 mm, proven bound 0.009627 mm, rounding included)
(T1: seed-ex-1)
(T1 plunge feed 200 mm/min)
(estimated cycle time 2 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 0.23 s; the exact path's bound on this machine 0.21 s [x1.070; rapids, plunges and pauses not counted])
(G01 where the tool speeds up or slows down, where that is faster: machine linuxcnc gives arcs less acceleration than lines)
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
X0.3766 Y0.0008 F600.
X0.5285 Y0.0191
X0.667 Y0.0382
G5.1 X1.3328 Y0.4618 I0.6846 J0.0946
G1 X1.3295 Y0.52
X1.1977 Y0.7893
X1. Y1.
G0 Z5.
M5
M30
%
