%
O1000 (BEZCAM)
N10 (bezcam 0.1.0: curve-semicircle.json, machine fanuc, output lines)
N20 (tolerance 0.005 mm; largest deviation measured 0.004446 mm, proven bound 0.004635 mm, rounding included)
N30 (T1: semicircle-r3)
N40 (T1 plunge feed 200 mm/min)
N50 (estimated cycle time 8 s on the motion model of machine fanuc [acceleration, corners, tool changes])
N60 (cutting along the curves 0.76 s; the exact path's bound on this machine 0.71 s [x1.067; rapids, plunges and pauses not counted])
N70 G21 G90 G17
N80 G40 G49 G80 G94
N90 G54
N100 G53 G00 Z0.
N110 T1 M06
N120 G43 H1
N130 S12000 M03
N140 (entity semicircle-r3: bezier, degree 3, 2D)
N150 G00 Z5.
N160 X-3. Y0.
N170 G01 Z-0.5 F200.
N180 X-2.983 Y0.399 F800.
N190 X-2.909 Y0.83
N200 X-2.783 Y1.225
N210 X-2.609 Y1.586
N220 X-2.387 Y1.912
N230 X-2.121 Y2.202
N240 X-1.81 Y2.454
N250 X-1.459 Y2.664
N260 X-1.072 Y2.827
N270 X-0.655 Y2.94
N280 X-0.221 Y2.997
N290 X0.221
N300 X0.655 Y2.94
N310 X1.072 Y2.827
N320 X1.459 Y2.664
N330 X1.81 Y2.454
N340 X2.121 Y2.202
N350 X2.387 Y1.912
N360 X2.609 Y1.586
N370 X2.783 Y1.225
N380 X2.909 Y0.83
N390 X2.983 Y0.399
N400 X3. Y0.
N410 G00 Z5.
N420 M05
N430 M30
%
