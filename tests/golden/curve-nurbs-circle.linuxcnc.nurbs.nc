%
(bezcam 0.1.0: curve-nurbs-circle.json, machine linuxcnc, output nurbs)
(tolerance 0.01 mm; largest deviation measured 6.578e-05 mm, proven bound 7.453e-05 mm, rounding included)
(T1: circle-d80)
(T1 plunge feed 300 mm/min)
(estimated cycle time 17 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 15.12 s; the exact path's bound on this machine 15.07 s [x1.003; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T1 M6
G43 H1
S12000 M3
(entity circle-d80: bspline, degree 2, rational, 2D)
G0 Z5.
X20. Y50.
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X20. Y10. P0.7071
X60. Y10. P1.
G5.3
G5.2 P1. L3
X100. Y10. P0.7071
X100. Y50. P1.
G5.3
G5.2 P1. L3
X100. Y90. P0.7071
X60. Y90. P1.
G5.3
G5.2 P1. L3
X20. Y90. P0.7071
X20. Y50. P1.
G5.3
G0 Z5.
M5
M30
%
