%
O1000 (BEZCAM)
(bezcam 0.1.0: path-closed-teardrop.json, machine fanuc-g063, output nurbs)
(tolerance 0.01 mm; largest deviation measured 0 mm, proven bound 0 mm, rounding included)
(T2: teardrop)
(T2 plunge feed 300 mm/min)
(estimated cycle time 14 s on the motion model of machine fanuc-g063 [acceleration, corners, tool changes])
(cutting along the curves 7.10 s; the exact path's bound on this machine 7.05 s [x1.005; rapids, plunges and pauses not counted])
G21 G90 G17
G53 G00 Z0.
T2 M06
S12000 M03
(entity teardrop: path, degree 3, 2D)
G00 Z5.
X0. Y0.
G01 Z-1. F300.
G06.3 P4 K0.000000 X0.000 Y0.000 Z-1.000 R1.000 F1000.
K0.000000 X20.000 Y10.000 Z-1.000 R1.000
K0.000000 X30.000 Y20.000 Z-1.000 R1.000
K0.000000 X30.000 Y30.000 Z-1.000 R1.000
K1.000000 X30.000 Y40.000 Z-1.000 R1.000
K1.000000 X20.000 Y45.000 Z-1.000 R1.000
K1.000000 X10.000 Y40.000 Z-1.000 R1.000
K2.000000 X0.000 Y35.000 Z-1.000 R1.000
K2.000000 X-10.000 Y20.000 Z-1.000 R1.000
K2.000000 X0.000 Y0.000 Z-1.000 R1.000
K3.000000
K3.000000
K3.000000
K3.000000
G00 Z5.
M05
M30
%
