%
(bezcam 0.1.0: path-closed-teardrop.json, machine linuxcnc, output nurbs)
(tolerance 0.01 mm; largest deviation measured 0 mm, proven bound 0 mm, rounding included)
(T2: teardrop)
(T2 plunge feed 300 mm/min)
(estimated cycle time 9 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 7.09 s; the exact path's bound on this machine 7.05 s [x1.004; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T2 M6
G43 H2
S12000 M3
(entity teardrop: path, degree 3, 2D)
G0 Z5.
X0. Y0.
G1 Z-1. F300.
G5 X30. Y30. I20. J10. P0. Q-10. F1000.
G5 X10. Y40. I0. J10. P10. Q5.
G5 X0. Y0. I-10. J-5. P-10. Q20.
G0 Z5.
M5
M30
%
