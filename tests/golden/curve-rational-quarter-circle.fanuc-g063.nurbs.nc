%
O1000 (BEZCAM)
(bezcam 0.1.0: curve-rational-quarter-circle.json, machine fanuc-g063, output nurbs)
(tolerance 0.01 mm; largest deviation measured 0.0002591 mm, proven bound 0.0002913 mm, rounding included)
(T1: quarter-circle-r10)
(T1 plunge feed 300 mm/min)
(estimated cycle time 8 s on the motion model of machine fanuc-g063 [acceleration, corners, tool changes])
(cutting along the curves 0.98 s; the exact path's bound on this machine 0.94 s [x1.040; rapids, plunges and pauses not counted])
G21 G90 G17
G53 G00 Z0.
T1 M06
S12000 M03
(entity quarter-circle-r10: bezier, degree 2, rational, 2D)
G00 Z5.
X10. Y0.
G01 Z-1. F300.
G06.3 P3 K0.000000 X10.000 Y0.000 Z-1.000 R1.000 F1000.
K0.000000 X10.000 Y10.000 Z-1.000 R0.707
K0.000000 X0.000 Y10.000 Z-1.000 R1.000
K1.000000
K1.000000
K1.000000
G00 Z5.
M05
M30
%
