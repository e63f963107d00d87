%
(bezcam 0.1.0: job-exercises-all.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009776 mm, proven bound 0.009996 mm, rounding included)
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
X0.732 Y0.039 F600.
X1.147 Y0.164
X1.316 Y0.326
X1.332 Y0.526
X1.165 Y0.831
X1. Y1.
G00 Z5.
(entity seed-ex-2: bezier, degree 2, 2D)
X8. Y0.
G01 Z-0.5 F200.
X8.627 Y-0.274 F600.
X9.035 Y-0.341
X9.239 Y-0.272
X9.335 Y-0.094
X9.304 Y0.267
X9.032 Y0.955
X9. Y1.
G00 Z5.
(entity seed-ex-3: bezier, degree 2, 2D)
X15. Y0.
G01 Z-0.5 F200.
X15.525 Y0.467 F600.
X16.103 Y0.808
X16.651 Y0.979
X17. Y1.
G00 Z5.
(entity seed-ex-4: bezier, degree 3, 2D)
X0. Y5.
G01 Z-0.5 F200.
X0.413 Y5.044 F600.
X0.862 Y5.231
X1.111 Y5.458
X1.161 Y5.649
X1.061 Y5.804
X0.749 Y5.939
X0.077 Y6.008
X0. Y6.
G00 Z5.
(entity seed-ex-5: bezier, degree 3, 2D)
X8. Y5.
G01 Z-0.5 F200.
X8.618 Y5.561 F600.
X9.186 Y5.914
X9.5 Y6.009
X9.358 Y6.02
X8.87 Y6.262
X8.206 Y6.789
X8. Y7.
G00 Z5.
(entity seed-ex-6: bezier, degree 3, 2D)
X16. Y5.
G01 Z-0.5 F200.
X16.511 Y5.041 F600.
X16.972 Y5.204
X17.291 Y5.453
X17.469 Y5.756
X17.504 Y6.083
X17.397 Y6.402
X17.148 Y6.681
X16.757 Y6.891
X16.225 Y7.
X16.
G00 Z5.
(entity seed-ex-7: bezier, degree 3, 2D)
X0. Y10.
G01 Z-0.5 F200.
X0.708 Y10.657 F600.
X1.119 Y10.907
X1.37 Y10.933
X1.841 Y10.714
X2.204 Y10.706
X2.748 Y10.873
X3. Y11.
G00 Z5.
(entity seed-ex-8: bezier, degree 3, 2D)
X8. Y10.
G01 Z-0.5 F200.
X8.401 Y10.036 F600.
X8.564 Y10.146
X8.573 Y10.308
X8.36 Y10.637
X7.56 Y11.461
X7.416 Y11.736
X7.456 Y11.883
X7.67 Y11.982
X8. Y12.
G00 Z5.
(entity seed-ex-9: bezier, degree 4, 2D)
X16. Y9.
G01 Z-0.5 F200.
X16.34 Y9.756 F600.
X16.39 Y10.082
X16.308 Y10.213
X16.029 Y10.259
X15.741 Y10.261
X15.619 Y10.351
X15.632 Y10.53
X15.887 Y10.895
X16. Y11.
G00 Z5.
M05
M30
%
