%
(bezcam 0.1.0: logo.svg, machine generic, output arcs)
(tolerance 0.01 mm; largest deviation measured 0.009937 mm, proven bound 0.009974 mm, rounding included)
(T1: dot, b, b.2, z, wave, eye, frame)
(estimated cycle time 36 s on the motion model of machine generic [acceleration, corners, tool changes])
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
G02 X32.595 Y13.682 I2.202 J-1.488
G02 X33.979 Y13.351 I0.404 J-1.367
G02 X35.25 Y11.64 I-3.831 J-4.174
G02 X36. Y10. I-14.774 J-7.746
G03 X37.453 Y7.247 I11.031 J4.062
G03 X38.601 Y6.316 I2.152 J1.48
G03 X39.982 Y6.652 I0.398 J1.37
G03 X41.25 Y8.359 I-3.84 J4.177
G03 X42. Y10. I-14.773 J7.744
G02 X43.61 Y11.963 I6.193 J-3.437
G02 X45.371 Y12.462 I1.411 J-1.622
G02 X46.895 Y11.502 I-0.787 J-2.939
G02 X48. Y10. I-6.384 J-5.854
G03 X49.606 Y8.04 I6.203 J3.444
G03 X51.362 Y7.536 I1.417 J1.625
G03 X52.881 Y8.483 I-0.766 J2.92
G03 X54. Y10. I-6.331 J5.841
G00 Z5.
(entity eye: path, degree 2, rational, 2D)
X52.819 Y23.026
G01 Z-1. F300.
G02 X52.603 Y22.031 I-1.08 J-0.286 F1000.
G02 X50.857 Y20.728 I-3.257 J2.543
G01 X50.513 Y20.59
G02 X48.127 Y20.317 I-1.694 J4.24
G02 X47.22 Y20.885 I0.155 J1.256
G01 X47.181 Y20.974
G02 X47.4 Y21.973 I1.082 J0.286
G02 X49.147 Y23.274 I3.26 J-2.554
G01 X49.487 Y23.41
G02 X51.873 Y23.683 I1.694 J-4.24
G02 X52.78 Y23.116 I-0.156 J-1.259
G01 X52.819 Y23.026
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
