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
X0.662 Y0.028 F600.
X1.094 Y0.138
X1.29 Y0.283
X1.342 Y0.465
X1.251 Y0.709
X1. Y1.
G00 Z5.
(entity seed-ex-2: bezier, degree 2, 2D)
X8. Y0.
G01 Z-0.5 F200.
X8.553 Y-0.249 F600.
X8.953 Y-0.341
X9.183 Y-0.307
X9.307 Y-0.183
X9.341 Y0.047
X9.249 Y0.447
X9. Y1.
G00 Z5.
(entity seed-ex-3: bezier, degree 2, 2D)
X15. Y0.
G01 Z-0.5 F200.
X15.493 Y0.444 F600.
X16.041 Y0.78
X16.563 Y0.961
X17. Y1.
G00 Z5.
(entity seed-ex-4: bezier, degree 3, 2D)
X0. Y5.
G01 Z-0.5 F200.
X0.371 Y5.034 F600.
X0.779 Y5.184
X1.05 Y5.381
X1.159 Y5.568
X1.128 Y5.732
X0.956 Y5.868
X0.573 Y5.973
X0. Y6.
G00 Z5.
(entity seed-ex-5: bezier, degree 3, 2D)
X8. Y5.
G01 Z-0.5 F200.
X8.537 Y5.497 F600.
X9.055 Y5.849
X9.427 Y5.998
X9.499 Y6.009
X9.464 Y5.995
X9.096 Y6.13
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
X0.612 Y10.58 F600.
X1.021 Y10.864
X1.275 Y10.94
X1.506 Y10.882
X1.775 Y10.732
X2.09 Y10.694
X2.505 Y10.781
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
