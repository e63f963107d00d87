%
(bezcam 0.1.0: curve-cube-3d.json, machine linuxcnc, output nurbs)
(tolerance 0.001 mm; largest deviation measured 0.0009976 mm, proven bound 0.0009996 mm, rounding included)
(T1: cube-base-curve)
(T1 plunge feed 100 mm/min)
(estimated cycle time 4 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 0.28 s; the exact path's bound on this machine 0.25 s [x1.077; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T1 M6
G43 H1
S12000 M3
(entity cube-base-curve: bezier, degree 3, 3D)
G0 Z5.
X0. Y0.
G1 Z0. F100.
(not exact: z varies, and G5/G5.2 move in X and Y only)
X0.1249 Y0.0046 F500.
X0.2558 Y0.0238 Z0.0007
X0.373 Y0.0554 Z0.0028
X0.4787 Y0.0985 Z0.0072
X0.5732 Y0.152 Z0.0148
X0.6579 Y0.2158 Z0.0267
X0.7328 Y0.2887 Z0.0445
X0.7976 Y0.3694 Z0.0695
X0.8525 Y0.4562 Z0.1038
X0.8964 Y0.5442 Z0.1478
X0.9306 Y0.631 Z0.2027
X0.9558 Y0.7123 Z0.2681
X0.9737 Y0.7861 Z0.3442
X0.9856 Y0.8502 Z0.4302
X0.993 Y0.9036 Z0.5256
X0.9973 Y0.9461 Z0.6314
X0.9993 Y0.9771 Z0.7491
X1. Y0.9957 Z0.8788
Y1. Z1.
G0 Z5.
M5
M30
%
