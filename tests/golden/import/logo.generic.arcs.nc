%
(bezcam 0.1.0: logo.svg, machine generic, output arcs)
(tolerance 0.01 mm; largest deviation measured 0.00675 mm, proven bound 0.006763 mm, rounding included)
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
G02 X30.914 Y11.937 I14.365 J-5.594 F1000.
G02 X31.659 Y13. I5.624 J-3.149
G02 X32.332 Y13.564 I2.071 J-1.787
G02 X33.618 Y13.591 I0.667 J-1.12
G02 X34.301 Y13.045 I-1.164 J-2.156
G02 X35.221 Y11.696 I-5.208 J-4.54
G02 X36. Y10. I-16.723 J-8.708
G03 X36.759 Y8.343 I17.457 J6.994
G03 X37.547 Y7.13 I6.557 J3.397
G03 X38.224 Y6.501 I2.448 J1.956
G03 X39.061 Y6.252 I0.805 J1.174
G03 X39.574 Y6.387 I-0.026 J1.141
G03 X40.401 Y7.068 I-1.292 J2.411
G03 X41.299 Y8.452 I-5.867 J4.79
G03 X42. Y10. I-18.422 J9.275
G02 X43.01 Y11.4 I7.763 J-4.536
G02 X43.902 Y12.165 I3.144 J-2.763
G02 X44.955 Y12.499 I1.152 J-1.805
G02 X45.682 Y12.371 I0.078 J-1.686
G02 X46.721 Y11.677 I-1.244 J-2.987
G02 X48. Y10. I-5.487 J-5.511
G03 X49.179 Y8.421 I6.83 J3.87
G03 X50.045 Y7.753 I2.695 J2.598
G03 X51.856 Y7.704 I0.952 J1.699
G03 X52.729 Y8.33 I-1.44 J2.93
G03 X54. Y10. I-5.611 J5.589
G00 Z5.
(entity eye: path, degree 2, rational, 2D)
X52.819 Y23.026
G01 Z-1. F300.
G02 X52.787 Y22.371 I-0.879 J-0.285 F1000.
G02 X52.242 Y21.614 I-2.029 J0.886
G02 X50.513 Y20.59 I-3.391 J3.754
G02 X49.362 Y20.3 I-2.22 J6.382
G02 X48.138 Y20.314 I-0.572 J3.567
G02 X47.493 Y20.577 I0.307 J1.676
G02 X47.181 Y20.974 I0.46 J0.683
G02 X47.167 Y21.489 I0.752 J0.278
G02 X47.6 Y22.224 I1.769 J-0.547
G02 X48.885 Y23.152 I3.184 J-3.055
G02 X49.487 Y23.41 I3.524 J-7.391
G02 X51.297 Y23.743 I1.805 J-4.725
G02 X52.161 Y23.602 I-0.002 J-2.733
G02 X52.687 Y23.256 I-0.388 J-1.163
G02 X52.819 Y23.026 I-0.479 J-0.428
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
