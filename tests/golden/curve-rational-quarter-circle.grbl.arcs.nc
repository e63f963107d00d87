(bezcam 0.1.0: curve-rational-quarter-circle.json, machine grbl, output arcs)
(tolerance 0.01 mm; largest deviation measured below 8.181e-07 mm, proven bound 8.182e-07 mm, rounding included)
(T1: quarter-circle-r10)
(T1 plunge feed 300 mm/min)
(estimated cycle time 5 s on the motion model of machine grbl [acceleration, corners, tool changes])
(cutting along the curves 0.97 s; the exact path's bound on this machine 0.94 s [x1.033; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
G54
(tool 1: load it before starting)
S12000 M3
G4 P2.
(entity quarter-circle-r10: bezier, degree 2, rational, 2D)
G0 Z5.
X10. Y0.
G1 Z-1. F300.
G3 X0. Y10. I-10. J0. F1000.
G0 Z5.
M5
M30
