%
(bezcam 0.1.0: curve-helix-xz.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009559 mm, proven bound 0.009991 mm, rounding included)
(T3: groove-xz, arch-yz)
(T3 plunge feed 200 mm/min)
(estimated cycle time 17 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 6.36 s; the exact path's bound on this machine 6.30 s [x1.010; rapids, plunges and pauses not counted])
(order shortest: 0 nested contours cut before what encloses them; rapids 30 mm in XY instead of 38.3 mm as written [8.3 mm saved])
G21 G90 G17
G40 G49 G80 G94
T3 M06
S12000 M03
(entity groove-xz: path, degree 3, 3D)
G00 Z5.
X-10. Y0.
G01 Z0. F200.
X-9.955 Y0.635 Z-1.041 F600.
X-9.761 Y1.381 Z-2.222
X-9.427 Y2.138 Z-3.37
X-8.958 Y2.906 Z-4.47
X-8.358 Y3.682 Z-5.509
X-7.636 Y4.464 Z-6.471
X-6.803 Y5.248 Z-7.341
X-5.873 Y6.031 Z-8.105
X-4.861 Y6.809 Z-8.751
X-3.781 Y7.58 Z-9.27
X-2.65 Y8.341 Z-9.654
X-1.48 Y9.091 Z-9.9
X-0.285 Y9.829 Z-10.005
X0. Y10. Z-10.
X1.041 Y10.635 Z-9.955
X2.222 Y11.381 Z-9.761
X3.37 Y12.138 Z-9.427
X4.47 Y12.906 Z-8.958
X5.509 Y13.682 Z-8.358
X6.471 Y14.464 Z-7.636
X7.341 Y15.248 Z-6.803
X8.105 Y16.031 Z-5.873
X8.751 Y16.809 Z-4.861
X9.27 Y17.58 Z-3.781
X9.654 Y18.341 Z-2.65
X9.9 Y19.091 Z-1.48
X10.005 Y19.829 Z-0.285
X10. Y20. Z0.
G00 Z5.
(entity arch-yz: bezier, degree 3, 3D)
X30.
G01 Z0. F200.
Y19.957 Z-0.689 F600.
Y19.773 Z-1.442
Y19.454 Z-2.154
Y18.994 Z-2.83
Y18.385 Z-3.47
Y17.588 Z-4.085
Y16.61 Z-4.646
Y15.445 Z-5.136
Y14.101 Z-5.536
Y12.606 Z-5.824
Y11.004 Z-5.982
Y9.358 Z-5.998
Y7.741 Z-5.871
Y6.218 Z-5.61
Y4.842 Z-5.234
Y3.642 Z-4.766
Y2.629 Z-4.225
Y1.8 Z-3.629
Y1.142 Z-2.992
Y0.643 Z-2.319
Y0.289 Z-1.61
Y0.073 Z-0.863
Y-0.008 Z-0.069
Y0. Z0.
G00 Z5.
M05
M30
%
