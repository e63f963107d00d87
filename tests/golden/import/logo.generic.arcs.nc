%
(bezcam 0.1.0: logo.svg, machine generic, output arcs)
(tolerance 0.01 mm; largest deviation measured 0.009976 mm, proven bound 0.009982 mm, rounding included)
(T1: dot, b, b.2, z, wave, eye, frame)
(T1 plunge feed 300 mm/min)
(estimated cycle time 36 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 17.56 s; the exact path's bound on this machine 17.40 s [x1.009; rapids, plunges and pauses not counted])
(order shortest: 6 nested contours cut before what encloses them; rapids 53.1 mm in XY instead of 118.5 mm as written [65.4 mm saved])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S10000 M03
(entity dot: path, degree 2, rational, 2D)
G00 Z5.
X7. Y6.
G01 Z-1. F300.
G02 X8. Y5. I0. J-1. F1000.
G02 X7. Y4. I-1. J0.
G02 X6. Y5. I0. J1.
G02 X7. Y6. I1. J0.
G00 Z5.
(entity b: path, degree 1, 2D)
G01 Z-1. F300.
Y24. F1000.
G00 Z5.
(entity b.2: path, degree 2, rational, 2D)
X11. Y14.
G01 Z-1. F300.
G02 X15. Y10. I0. J-4. F1000.
G02 X11. Y6. I-4. J0.
G02 X7. Y10. I0. J4.
G02 X11. Y14. I4. J0.
G00 Z5.
(entity z: path, degree 1, 2D)
X19.
G01 Z-1. F300.
X26. F1000.
X19. Y6.
X26.
G00 Z5.
(entity wave: path, degree 3, 2D)
X30. Y10.
G01 Z-1. F300.
G02 X31.43 Y12.723 I11.159 J-4.123 F1000.
G02 X32.511 Y13.651 I2.371 J-1.668
G02 X33.965 Y13.362 I0.494 J-1.316
G02 X35.229 Y11.679 I-3.724 J-4.113
G03 X35.683 Y10.751 I279.841 J136.33
G02 X36. Y10. I-6.396 J-3.142
G03 X37.441 Y7.263 I11.096 J4.094
G03 X38.508 Y6.351 I2.337 J1.654
G03 X39.959 Y6.633 I0.498 J1.31
G03 X41.221 Y8.306 I-3.682 J4.09
G02 X41.68 Y9.242 I384.667 J-188.054
G03 X42. Y10. I-6.404 J3.15
G02 X43.61 Y11.963 I6.193 J-3.437
G02 X45.18 Y12.491 I1.447 J-1.704
G02 X46.712 Y11.686 I-0.413 J-2.646
G02 X48. Y10. I-5.702 J-5.691
G03 X49.473 Y8.147 I6.811 J3.902
G03 X50.976 Y7.5 I1.662 J1.791
G03 X52.55 Y8.167 I-0.089 J2.401
G03 X54. Y10. I-5.126 J5.545
G00 Z5.
(entity eye: path, degree 2, rational, 2D)
X52.819 Y23.026
G01 Z-1. F300.
G02 X52.603 Y22.031 I-1.08 J-0.286 F1000.
G02 X50.857 Y20.728 I-3.257 J2.543
G03 X50.513 Y20.59 I9.466 J-24.094
G02 X48.14 Y20.314 I-1.698 J4.258
G02 X47.265 Y20.808 I0.206 J1.387
G02 X47.181 Y20.974 I0.327 J0.27
G02 X47.394 Y21.965 I1.077 J0.287
G02 X49.083 Y23.246 I3.224 J-2.497
G01 X49.487 Y23.41
G02 X51.859 Y23.686 I1.698 J-4.26
G02 X52.723 Y23.208 I-0.206 J-1.393
G02 X52.819 Y23.026 I-0.356 J-0.304
G00 Z5.
(entity frame: path, degree 2, rational, 2D)
X55. Y29.
G01 Z-1. F300.
G02 X59. Y25. I0. J-4. F1000.
G01 Y5.
G02 X55. Y1. I-4. J0.
G01 X5.
G02 X1. Y5. I0. J4.
G01 Y25.
G02 X5. Y29. I4. J0.
G01 X55.
G00 Z5.
M05
M30
%
