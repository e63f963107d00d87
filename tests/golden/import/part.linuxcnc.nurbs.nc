%
(bezcam 0.1.0: part.dxf, machine linuxcnc, output nurbs)
(tolerance 0.01 mm; largest deviation measured below 1e-05 mm, proven bound 1.149e-05 mm, rounding included)
(T1: HOLES:37, HOLES:3A, HOLES:3B, HOLES:39, HOLES:38, OUTLINE:2F+7)
(estimated cycle time 34 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 23.18 s; the exact path's bound on this machine 23.03 s [x1.006; rapids, plunges and pauses not counted])
(order shortest: 5 nested contours cut before what encloses them; rapids 138.3 mm in XY instead of 194.5 mm as written [56.2 mm saved])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T1 M6
G43 H1
S10000 M3
(entity HOLES:37: path, degree 2, rational, 2D)
G0 Z5.
X7.5 Y10.
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X7.5 Y7.5 P0.7071
X10. Y7.5 P1.
G5.3
G5.2 P1. L3
X12.5 Y7.5 P0.7071
X12.5 Y10. P1.
G5.3
G5.2 P1. L3
X12.5 Y12.5 P0.7071
X10. Y12.5 P1.
G5.3
G5.2 P1. L3
X7.5 Y12.5 P0.7071
X7.5 Y10. P1.
G5.3
G0 Z5.
(entity HOLES:3A: path, degree 2, rational, 2D)
X10. Y37.5
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X12.5 Y37.5 P0.7071
X12.5 Y40. P1.
G5.3
G5.2 P1. L3
X12.5 Y42.5 P0.7071
X10. Y42.5 P1.
G5.3
G5.2 P1. L3
X7.5 Y42.5 P0.7071
X7.5 Y40. P1.
G5.3
G5.2 P1. L3
X7.5 Y37.5 P0.7071
X10. Y37.5 P1.
G5.3
G0 Z5.
(entity HOLES:3B: path, degree 2, rational, 2D)
X50. Y30.
G1 Z-1. F300.
X30. F1000.
G5.2 P1. L3
X25. Y30. P0.7071
X25. Y25. P1.
G5.3
G5.2 P1. L3
X25. Y20. P0.7071
X30. Y20. P1.
G5.3
G1 X50.
G5.2 P1. L3
X55. Y20. P0.7071
X55. Y25. P1.
G5.3
G5.2 P1. L3
X55. Y30. P0.7071
X50. Y30. P1.
G5.3
G0 Z5.
(entity HOLES:39: path, degree 2, rational, 2D)
X70. Y37.5
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X72.5 Y37.5 P0.7071
X72.5 Y40. P1.
G5.3
G5.2 P1. L3
X72.5 Y42.5 P0.7071
X70. Y42.5 P1.
G5.3
G5.2 P1. L3
X67.5 Y42.5 P0.7071
X67.5 Y40. P1.
G5.3
G5.2 P1. L3
X67.5 Y37.5 P0.7071
X70. Y37.5 P1.
G5.3
G0 Z5.
(entity HOLES:38: path, degree 2, rational, 2D)
X72.5 Y10.
G1 Z-1. F300.
G5.2 P1. L3 F1000.
X72.5 Y12.5 P0.7071
X70. Y12.5 P1.
G5.3
G5.2 P1. L3
X67.5 Y12.5 P0.7071
X67.5 Y10. P1.
G5.3
G5.2 P1. L3
X67.5 Y7.5 P0.7071
X70. Y7.5 P1.
G5.3
G5.2 P1. L3
X72.5 Y7.5 P0.7071
X72.5 Y10. P1.
G5.3
G0 Z5.
(entity OUTLINE:2F+7: path, degree 2, rational, 2D)
X80. Y6.
G1 Z-1. F300.
Y44. F1000.
G5.2 P1. L3
X80. Y50. P0.7071
X74. Y50. P1.
G5.3
G1 X6.
G5.2 P1. L3
X0. Y50. P0.7071
X0. Y44. P1.
G5.3
G1 Y6.
G5.2 P1. L3
X0. Y0. P0.7071
X6. Y0. P1.
G5.3
G1 X74.
G5.2 P1. L3
X80. Y0. P0.7071
X80. Y6. P1.
G5.3
G0 Z5.
M5
M30
%
