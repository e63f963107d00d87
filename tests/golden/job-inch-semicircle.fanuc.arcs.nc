%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: job-inch-semicircle.json, machine fanuc, output arcs)
N20 (tolerance 0.0005 inch; largest deviation measured 0.0002611 inch, proven bound 0.0002618 inch, rounding included)
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
N180 G02 X-2.959 Y0.5538 I3.6541 J0.0079 F40.
N190 G02 X-2.8249 Y1.1009 I3.0843 J-0.466
N200 G02 X-2.4842 Y1.7749 I2.6104 J-0.8964
N210 G02 X-2.103 Y2.2133 I2.1672 J-1.4995
N220 G02 X-1.5154 Y2.63 I1.9153 J-2.0782
N230 G02 X-0.8777 Y2.8828 I1.4465 J-2.7182
N240 G02 X0.7442 Y2.9164 I0.8781 J-3.2255
N250 G02 X1.3547 Y2.7097 I-0.7036 J-3.0831
N260 G02 X1.9564 Y2.3396 I-1.1973 J-2.6207
N270 G02 X2.6734 Y1.4581 I-1.6735 J-2.0936
N280 G02 X2.8769 Y0.935 I-2.5514 J-1.2937
N290 G02 X2.9776 Y0.4133 I-3.121 J-0.873
N300 G02 X3. Y0. I-3.7791 J-0.4121
N310 G00 Z0.25
N320 M05
N330 M30
%
