%
(bezcam 0.1.0: job-inch-semicircle.json, machine generic, output arcs)
(tolerance 0.0005 inch; largest deviation measured 0.000498 inch, proven bound 0.0005 inch, rounding included)
(T1: semicircle-inch)
(estimated cycle time 16 s: feeds as programmed, rapids at 787.402 inch/min, no acceleration, tool changes not counted)
G20 G90 G17
G40 G49 G80 G94
T1 M06
S10000 M03
(entity semicircle-inch: bezier, degree 3, 2D)
G00 Z0.25
X-3. Y0.
G01 Z-0.02 F10.
G02 X-2.892 Y0.8791 I3.4734 J0.0195 F40.
G02 X-2.4379 Y1.8395 I2.709 J-0.6933
G02 X-1.5177 Y2.6288 I2.2096 J-1.645
G02 X-0.3664 Y2.98 I1.4846 J-2.804
G02 X1.145 Y2.7967 I0.3675 J-3.2927
G02 X2.0886 Y2.2265 I-0.9978 J-2.7171
G02 X2.8338 Y1.0745 I-1.8336 J-2.0031
G02 X2.9941 Y0.2141 I-3.1087 J-1.0243
G02 X3. Y0. I-3.8549 J-0.213
G00 Z0.25
M05
M30
%
