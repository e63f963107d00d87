%
(bezcam 0.1.0: part.dxf, machine generic, output arcs)
(tolerance 0.01 mm; largest deviation measured below 8.181e-07 mm, proven bound 8.182e-07 mm, rounding included)
(T1: HOLES:37, HOLES:3A, HOLES:3B, HOLES:39, HOLES:38, OUTLINE:2F+7)
(estimated cycle time 41 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 23.14 s; the exact path's bound on this machine 23.03 s [x1.005; rapids, plunges and pauses not counted])
(order shortest: 5 nested contours cut before what encloses them; rapids 138.3 mm in XY instead of 194.5 mm as written [56.2 mm saved])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S10000 M03
(entity HOLES:37: path, degree 2, rational, 2D)
G00 Z5.
X7.5 Y10.
G01 Z-1. F300.
G03 X10. Y7.5 I2.5 J0. F1000.
G03 X12.5 Y10. I0. J2.5
G03 X10. Y12.5 I-2.5 J0.
G03 X7.5 Y10. I0. J-2.5
G00 Z5.
(entity HOLES:3A: path, degree 2, rational, 2D)
X10. Y37.5
G01 Z-1. F300.
G03 X12.5 Y40. I0. J2.5 F1000.
G03 X10. Y42.5 I-2.5 J0.
G03 X7.5 Y40. I0. J-2.5
G03 X10. Y37.5 I2.5 J0.
G00 Z5.
(entity HOLES:3B: path, degree 2, rational, 2D)
X50. Y30.
G01 Z-1. F300.
X30. F1000.
G03 X25. Y25. I0. J-5.
G03 X30. Y20. I5. J0.
G01 X50.
G03 X55. Y25. I0. J5.
G03 X50. Y30. I-5. J0.
G00 Z5.
(entity HOLES:39: path, degree 2, rational, 2D)
X70. Y37.5
G01 Z-1. F300.
G03 X72.5 Y40. I0. J2.5 F1000.
G03 X70. Y42.5 I-2.5 J0.
G03 X67.5 Y40. I0. J-2.5
G03 X70. Y37.5 I2.5 J0.
G00 Z5.
(entity HOLES:38: path, degree 2, rational, 2D)
X72.5 Y10.
G01 Z-1. F300.
G03 X70. Y12.5 I-2.5 J0. F1000.
G03 X67.5 Y10. I0. J-2.5
G03 X70. Y7.5 I2.5 J0.
G03 X72.5 Y10. I0. J2.5
G00 Z5.
(entity OUTLINE:2F+7: path, degree 2, rational, 2D)
X80. Y6.
G01 Z-1. F300.
Y44. F1000.
G03 X74. Y50. I-6. J0.
G01 X6.
G03 X0. Y44. I0. J-6.
G01 Y6.
G03 X6. Y0. I6. J0.
G01 X74.
G03 X80. Y6. I0. J6.
G00 Z5.
M05
M30
%
