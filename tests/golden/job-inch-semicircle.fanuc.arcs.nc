%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: job-inch-semicircle.json, machine fanuc, output arcs)
N20 (tolerance 0.0005 inch; largest deviation measured 0.0004979 inch, proven bound 0.0005 inch, rounding included)
N30 (T1: semicircle-inch)
N40 (T1 plunge feed 10 in/min)
N50 (estimated cycle time 22 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 14.31 s; the exact path's bound on this machine 14.27 s [x1.003; rapids, plunges and pauses not counted])
N70 G20 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S10000 M03
N140 (entity semicircle-inch: bezier, degree 3, 2D)
N150 G00 Z0.25
N160 X-3. Y0.
N170 G01 Z-0.02 F10.
N180 G02 X-2.892 Y0.8791 I3.4734 J0.0195 F40.
N190 G02 X-2.4379 Y1.8395 I2.709 J-0.6933
N200 G02 X-1.5177 Y2.6288 I2.2096 J-1.645
N210 G02 X-0.3983 Y2.9764 I1.4832 J-2.8002
N220 G02 X1.1288 Y2.8027 I0.3989 J-3.2928
N230 G02 X2.0383 Y2.2713 I-0.9913 J-2.7407
N240 G02 X2.837 Y1.0649 I-1.7827 J-2.0478
N250 G02 X2.9945 Y0.2074 I-3.1153 J-1.0154
N260 G02 X3. Y0. I-4.776 J-0.2304
N270 G00 Z0.25
N280 M05
N290 M30
%
