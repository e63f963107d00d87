%
(bezcam 0.1.0: job-exercises-all.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009643 mm, proven bound 0.009992 mm, rounding included)
(T1: seed-ex-1, seed-ex-2, seed-ex-3, seed-ex-4, seed-ex-5, seed-ex-6, seed-ex-7, seed-ex-8, seed-ex-9)
(estimated cycle time 28 s on the motion model of machine generic [acceleration, corners, tool changes])
G21 G90 G17
G40 G49 G80 G94
T1 M06
S12000 M03
(entity seed-ex-1: bezier, degree 2, 2D)
G00 Z5.
X0. Y0.
G01 Z-0.5 F200.
X0.668 Y0.029 F600.
X1.097 Y0.139
X1.291 Y0.284
X1.342 Y0.462
X1.253 Y0.706
X1. Y1.
G00 Z5.
(entity seed-ex-2: bezier, degree 2, 2D)
X8. Y0.
G01 Z-0.5 F200.
X8.559 Y-0.251 F600.
X8.962 Y-0.341
X9.186 Y-0.306
X9.306 Y-0.186
X9.341 Y0.038
X9.251 Y0.441
X9. Y1.
G00 Z5.
(entity seed-ex-3: bezier, degree 2, 2D)
X15. Y0.
G01 Z-0.5 F200.
X15.493 Y0.444 F600.
X16.042 Y0.78
X16.564 Y0.962
X17. Y1.
G00 Z5.
(entity seed-ex-4: bezier, degree 3, 2D)
X0. Y5.
G01 Z-0.5 F200.
X0.372 Y5.035 F600.
X0.783 Y5.186
X1.057 Y5.389
X1.16 Y5.574
X1.129 Y5.731
X0.958 Y5.867
X0.575 Y5.972
X0. Y6.
G00 Z5.
(entity seed-ex-5: bezier, degree 3, 2D)
X8. Y5.
G01 Z-0.5 F200.
X8.53 Y5.491 F600.
X9.044 Y5.842
X9.417 Y5.996
X9.498 Y6.009
X9.465 Y5.995
X9.097 Y6.129
X8.562 Y6.483
X8. Y7.
G00 Z5.
(entity seed-ex-6: bezier, degree 3, 2D)
X16. Y5.
G01 Z-0.5 F200.
X16.484 Y5.035 F600.
X16.932 Y5.183
X17.252 Y5.411
X17.445 Y5.692
X17.509 Y6.
X17.445 Y6.308
X17.252 Y6.589
X16.932 Y6.817
X16.484 Y6.965
X16. Y7.
G00 Z5.
(entity seed-ex-7: bezier, degree 3, 2D)
X0. Y10.
G01 Z-0.5 F200.
X0.614 Y10.582 F600.
X1.023 Y10.865
X1.273 Y10.94
X1.493 Y10.888
X1.791 Y10.727
X2.094 Y10.694
X2.504 Y10.78
X3. Y11.
G00 Z5.
(entity seed-ex-8: bezier, degree 3, 2D)
X8. Y10.
G01 Z-0.5 F200.
X8.359 Y10.024 F600.
X8.544 Y10.118
X8.584 Y10.261
X8.478 Y10.488
X8.006 Y11.006
X7.58 Y11.436
X7.421 Y11.712
X7.446 Y11.87
X7.628 Y11.973
X8. Y12.
G00 Z5.
(entity seed-ex-9: bezier, degree 4, 2D)
X16. Y9.
G01 Z-0.5 F200.
X16.34 Y9.756 F600.
X16.39 Y10.084
X16.305 Y10.215
X16.01 Y10.259
X15.739 Y10.262
X15.618 Y10.353
X15.634 Y10.535
X15.896 Y10.905
X16. Y11.
G00 Z5.
M05
M30
%
