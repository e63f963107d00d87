%
(bezcam 0.1.0: job-exercises-all.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009643 mm, proven bound 0.009993 mm, rounding included)
(T1: seed-ex-1, seed-ex-4, seed-ex-7, seed-ex-8, seed-ex-5, seed-ex-2, seed-ex-3, seed-ex-6, seed-ex-9)
(T1 plunge feed 200 mm/min)
(estimated cycle time 28 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 2.86 s; the exact path's bound on this machine 2.70 s [x1.054; rapids, plunges and pauses not counted])
(order shortest: 0 nested contours cut before what encloses them; rapids 33.4 mm in XY instead of 76.8 mm as written [43.4 mm saved])
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
(entity seed-ex-7: bezier, degree 3, 2D)
Y10.
G01 Z-0.5 F200.
X0.662 Y10.621 F600.
X1.082 Y10.893
X1.34 Y10.938
X1.574 Y10.836
X1.821 Y10.719
X2.116 Y10.695
X2.519 Y10.785
X3. Y11.
G00 Z5.
(entity seed-ex-8: bezier, degree 3, 2D)
X8. Y12.
G01 Z-0.5 F200.
X7.634 Y11.974 F600.
X7.45 Y11.876
X7.418 Y11.725
X7.552 Y11.471
X8. Y11.
X8.448 Y10.529
X8.582 Y10.275
X8.55 Y10.124
X8.366 Y10.026
X8. Y10.
G00 Z5.
(entity seed-ex-5: bezier, degree 3, 2D)
Y7.
G01 Z-0.5 F200.
X8.482 Y6.547 F600.
X8.96 Y6.205
X9.332 Y6.028
X9.5 Y6.
X9.332 Y5.972
X8.96 Y5.795
X8.482 Y5.453
X8. Y5.
G00 Z5.
(entity seed-ex-2: bezier, degree 2, 2D)
Y0.
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
(entity seed-ex-9: bezier, degree 4, 2D)
Y9.
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
