%
(bezcam 0.1.0: path-mixed-closed-keyhole.json, machine linuxcnc, output nurbs)
(tolerance 0.01 mm; largest deviation measured 2.565e-05 mm, proven bound 2.795e-05 mm, rounding included)
(T3: keyhole)
(estimated cycle time 10 s: feeds as programmed, rapids at 10000 mm/min, no acceleration, tool changes not counted)
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T3 M6
G43 H3
S16000 M3
(entity keyhole: path, degree 2, rational, 2D)
G0 Z5.
X15. Y30.
G1 Z-1. F300.
G5.2 P1. L3 F900.
X15. Y45. P0.7071
X0. Y45. P1.
G5.3
G5.2 P1. L3
X-15. Y45. P0.7071
X-15. Y30. P1.
G5.3
G5.2 P1. L3
X-15. Y15. P0.7071
X0. Y15. P1.
G5.3
G1 Y0.
X15.
Y30.
G0 Z5.
M5
M30
%
