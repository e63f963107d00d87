%
(bezcam 0.1.0: path-mixed-closed-keyhole.json, machine generic, output lines)
(tolerance 0.01 mm; largest deviation measured 0.009764 mm, proven bound 0.009982 mm, rounding included)
(T3: keyhole)
(T3 plunge feed 300 mm/min)
(estimated cycle time 17 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 8.76 s; the exact path's bound on this machine 8.71 s [x1.005; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
T3 M06
S16000 M03
(entity keyhole: path, degree 2, rational, 2D)
G00 Z5.
X0. Y0.
G01 Z-1. F300.
X15. F900.
Y20.
Y30.
X14.955 Y31.27
X14.758 Y32.735
X14.418 Y34.169
X13.942 Y35.557
X13.33 Y36.897
X12.592 Y38.167
X11.724 Y39.371
X10.756 Y40.468
X9.685 Y41.466
X8.527 Y42.351
X7.262 Y43.135
X5.944 Y43.782
X4.554 Y44.301
X3.154 Y44.674
X1.723 Y44.91
X0.239 Y45.007
X0. Y45.
X-1.27 Y44.955
X-2.735 Y44.758
X-4.169 Y44.418
X-5.557 Y43.942
X-6.897 Y43.33
X-8.167 Y42.592
X-9.371 Y41.724
X-10.468 Y40.756
X-11.466 Y39.685
X-12.351 Y38.527
X-13.135 Y37.262
X-13.782 Y35.944
X-14.301 Y34.554
X-14.674 Y33.154
X-14.91 Y31.723
X-15.006 Y30.282
X-15. Y30.
X-14.955 Y28.73
X-14.758 Y27.265
X-14.418 Y25.831
X-13.942 Y24.443
X-13.33 Y23.103
X-12.592 Y21.833
X-11.724 Y20.629
X-10.756 Y19.532
X-9.685 Y18.534
X-8.527 Y17.649
X-7.262 Y16.865
X-5.944 Y16.218
X-4.554 Y15.699
X-3.154 Y15.326
X-1.723 Y15.09
X-0.282 Y14.994
X0. Y15.
Y0.
G00 Z5.
M05
M30
%
