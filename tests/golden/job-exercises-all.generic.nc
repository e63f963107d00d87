%
(bezcam 0.1.0: job-exercises-all.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009676 mm, proven bound 0.009992 mm, rounding included)
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
X0.716 Y0.036 F600.
X1.138 Y0.159
X1.312 Y0.318
X1.337 Y0.501
X1.221 Y0.755
X1. Y1.
G00 Z5.
(entity seed-ex-2: bezier, degree 2, 2D)
X8. Y0.
G01 Z-0.5 F200.
X8.629 Y-0.274 F600.
X9.034 Y-0.341
X9.241 Y-0.271
X9.331 Y-0.114
X9.323 Y0.18
X9.111 Y0.788
X9. Y1.
G00 Z5.
(entity seed-ex-3: bezier, degree 2, 2D)
X15. Y0.
G01 Z-0.5 F200.
X15.532 Y0.472 F600.
X16.114 Y0.814
X16.657 Y0.98
X17. Y1.
G00 Z5.
(entity seed-ex-4: bezier, degree 3, 2D)
X0. Y5.
G01 Z-0.5 F200.
X0.415 Y5.045 F600.
X0.859 Y5.229
X1.108 Y5.453
X1.162 Y5.642
X1.078 Y5.79
X0.824 Y5.918
X0.233 Y6.004
X0. Y6.
G00 Z5.
(entity seed-ex-5: bezier, degree 3, 2D)
X8. Y5.
G01 Z-0.5 F200.
X8.616 Y5.559 F600.
X9.164 Y5.904
X9.499 Y6.009
X9.393 Y6.01
X8.939 Y6.218
X8.326 Y6.68
X8. Y7.
G00 Z5.
(entity seed-ex-6: bezier, degree 3, 2D)
X16. Y5.
G01 Z-0.5 F200.
X16.52 Y5.043 F600.
X16.983 Y5.21
X17.299 Y5.462
X17.473 Y5.768
X17.503 Y6.098
X17.389 Y6.416
X17.134 Y6.692
X16.735 Y6.898
X16.195 Y7.002
X16. Y7.
G00 Z5.
(entity seed-ex-7: bezier, degree 3, 2D)
X0. Y10.
G01 Z-0.5 F200.
X0.693 Y10.646 F600.
X1.111 Y10.904
X1.353 Y10.936
X1.575 Y10.845
X1.779 Y10.731
X2.116 Y10.695
X2.556 Y10.798
X3. Y11.
G00 Z5.
(entity seed-ex-8: bezier, degree 3, 2D)
X8. Y10.
G01 Z-0.5 F200.
X8.393 Y10.033 F600.
X8.561 Y10.14
X8.581 Y10.279
X8.457 Y10.517
X7.752 Y11.253
X7.47 Y11.595
X7.415 Y11.795
X7.496 Y11.917
X7.725 Y11.992
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
