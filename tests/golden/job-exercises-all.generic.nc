%
(bezcam 0.1.0: job-exercises-all.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009777 mm, proven bound 0.00998 mm, rounding included)
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
X0.629 Y0.033 F600.
X1.003 Y0.112
X1.208 Y0.213
X1.307 Y0.329
X1.333 Y0.464
X1.28 Y0.641
X1.112 Y0.88
X1. Y1.
G00 Z5.
(entity seed-ex-2: bezier, degree 2, 2D)
X8. Y0.
G01 Z-0.5 F200.
X8.553 Y-0.24 F600.
X8.898 Y-0.326
X9.112 Y-0.322
X9.241 Y-0.258
X9.314 Y-0.141
X9.331 Y0.054
X9.265 Y0.371
X9.064 Y0.868
X9. Y1.
G00 Z5.
(entity seed-ex-3: bezier, degree 2, 2D)
X15. Y0.
G01 Z-0.5 F200.
X15.455 Y0.403 F600.
X15.881 Y0.687
X16.286 Y0.872
X16.675 Y0.974
X17. Y1.
G00 Z5.
(entity seed-ex-4: bezier, degree 3, 2D)
X0. Y5.
G01 Z-0.5 F200.
X0.346 Y5.038 F600.
X0.688 Y5.15
X0.953 Y5.305
X1.103 Y5.462
X1.154 Y5.599
X1.126 Y5.718
X1.013 Y5.827
X0.775 Y5.923
X0.365 Y5.987
X0. Y6.
G00 Z5.
(entity seed-ex-5: bezier, degree 3, 2D)
X8. Y5.
G01 Z-0.5 F200.
X8.531 Y5.481 F600.
X8.97 Y5.79
X9.312 Y5.955
X9.491 Y6.
X9.236 Y6.074
X8.86 Y6.279
X8.396 Y6.632
X8. Y7.
G00 Z5.
(entity seed-ex-6: bezier, degree 3, 2D)
X16. Y5.
G01 Z-0.5 F200.
X16.44 Y5.036 F600.
X16.801 Y5.135
X17.085 Y5.284
X17.296 Y5.471
X17.432 Y5.685
X17.495 Y5.915
X17.485 Y6.149
X17.401 Y6.376
X17.244 Y6.585
X17.012 Y6.763
X16.706 Y6.899
X16.324 Y6.981
X16. Y7.
G00 Z5.
(entity seed-ex-7: bezier, degree 3, 2D)
X0. Y10.
G01 Z-0.5 F200.
X0.617 Y10.573 F600.
X0.973 Y10.828
X1.2 Y10.922
X1.371 Y10.923
X1.597 Y10.823
X1.844 Y10.722
X2.091 Y10.703
X2.42 Y10.763
X2.872 Y10.938
X3. Y11.
G00 Z5.
(entity seed-ex-8: bezier, degree 3, 2D)
X8. Y10.
G01 Z-0.5 F200.
X8.349 Y10.031 F600.
X8.511 Y10.099
X8.572 Y10.189
X8.562 Y10.314
X8.442 Y10.522
X8.056 Y10.943
X7.589 Y11.438
X7.446 Y11.664
X7.425 Y11.8
X7.479 Y11.892
X7.625 Y11.963
X7.935 Y11.999
X8. Y12.
G00 Z5.
(entity seed-ex-9: bezier, degree 4, 2D)
X16. Y9.
G01 Z-0.5 F200.
X16.296 Y9.657 F600.
X16.381 Y9.971
X16.37 Y10.125
X16.303 Y10.206
X16.18 Y10.243
X15.748 Y10.269
X15.653 Y10.318
X15.615 Y10.405
X15.652 Y10.554
X15.815 Y10.798
X16. Y11.
G00 Z5.
M05
M30
%
