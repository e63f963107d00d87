%
(bezcam 0.1.0: logo.svg, machine linuxcnc, output nurbs)
(tolerance 0.01 mm; largest deviation measured 4.68e-05 mm, proven bound 4.929e-05 mm, rounding included)
(T1: dot, b, b.2, z, wave, eye, frame)
(T1 plunge feed 300 mm/min)
(estimated cycle time 29 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 17.72 s; the exact path's bound on this machine 17.40 s [x1.018; rapids, plunges and pauses not counted])
(order shortest: 6 nested contours cut before what encloses them; rapids 53.1 mm in XY instead of 118.5 mm as written [65.4 mm saved])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T1 M6
G43 H1
S10000 M3
(entity dot: path, degree 2, rational, 2D)
G0 Z5.
X7. Y6.
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X8. Y6. P0.7071
X8. Y5. P1.
G5.3
G5.2 P1. L3
X8. Y4. P0.7071
X7. Y4. P1.
G5.3
G5.2 P1. L3
X6. Y4. P0.7071
X6. Y5. P1.
G5.3
G5.2 P1. L3
X6. Y6. P0.7071
X7. Y6. P1.
G5.3
G0 Z5.
(entity b: path, degree 1, 2D)
G1 Z-1. F300.
Y24. F1000.
G0 Z5.
(entity b.2: path, degree 2, rational, 2D)
X11. Y14.
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X15. Y14. P0.7071
X15. Y10. P1.
G5.3
G5.2 P1. L3
X15. Y6. P0.7071
X11. Y6. P1.
G5.3
G5.2 P1. L3
X7. Y6. P0.7071
X7. Y10. P1.
G5.3
G5.2 P1. L3
X7. Y14. P0.7071
X11. Y14. P1.
G5.3
G0 Z5.
(entity z: path, degree 1, 2D)
X19.
G1 Z-1. F300.
X26. F1000.
X19. Y6.
X26.
G0 Z5.
(entity wave: path, degree 3, 2D)
X30. Y10.
G1 Z-1. F300.
G5 X36. Y10. I2. J5. P-2. Q5. F1000.
G5 X42. Y10. I2. J-5. P-2. Q-5.
G5.1 X48. Y10. I3. J5.
G5.1 X54. Y10. I3. J-5.
G0 Z5.
(entity eye: path, degree 2, rational, 2D)
X52.8191 Y23.0261
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X53.3321 Y21.6165 P0.7071
X50.513 Y20.5905 P1.
G5.3
G5.2 P1. L3
X47.694 Y19.5644 P0.7071
X47.1809 Y20.9739 P1.
G5.3
G5.2 P1. L3
X46.6679 Y22.3835 P0.7071
X49.487 Y23.4095 P1.
G5.3
G5.2 P1. L3
X52.306 Y24.4356 P0.7071
X52.8191 Y23.0261 P1.
G5.3
G0 Z5.
(entity frame: path, degree 2, rational, 2D)
X55. Y29.
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X59. Y29. P0.7071
X59. Y25. P1.
G5.3
G1 Y5.
G5.2 P1. L3
X59. Y1. P0.7071
X55. Y1. P1.
G5.3
G1 X5.
G5.2 P1. L3
X1. Y1. P0.7071
X1. Y5. P1.
G5.3
G1 Y25.
G5.2 P1. L3
X1. Y29. P0.7071
X5. Y29. P1.
G5.3
G1 X55.
G0 Z5.
M5
M30
%
