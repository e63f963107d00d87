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
N190 G02 X-2.7373 Y1.3235 I2.6877 J-0.6865
N200 G02 X-2.5133 Y1.7322 I2.6152 J-1.1676
N210 G02 X-2.2733 Y2.0408 I2.0898 J-1.3776
N220 G02 X-1.983 Y2.318 I2.1415 J-1.9521
N230 G02 X-1.6589 Y2.548 I1.6759 J-2.0182
N240 G02 X-1.3602 Y2.7072 I1.6881 J-2.8075
N250 G02 X-1.0603 Y2.8268 I1.1706 J-2.4995
N260 G02 X1.1268 Y2.8034 I1.06 J-3.1479
N270 G02 X2.0367 Y2.2727 I-0.9883 J-2.7399
N280 G02 X2.3706 Y1.9267 I-1.6807 J-1.956
N290 G02 X2.6776 Y1.4498 I-2.1699 J-1.7341
N300 G02 X2.8645 Y0.9775 I-2.442 J-1.2395
N310 G02 X2.9653 Y0.5114 I-3.2282 J-0.9421
N320 G02 X2.9995 Y0.061 I-3.378 J-0.483
N330 G01 X3. Y0.
N340 G00 Z0.25
N350 M05
N360 M30
%
