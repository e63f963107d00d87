%
(bezcam 0.1.0: path-closed-teardrop.json, machine linuxcnc, output arcs)
(tolerance 0.01 mm; largest deviation measured 0.00624 mm, proven bound 0.006245 mm, rounding included)
(T2: teardrop)
(T2 plunge feed 300 mm/min)
(estimated cycle time 9 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 7.09 s; the exact path's bound on this machine 7.05 s [x1.004; rapids, plunges and pauses not counted])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T2 M6
G43 H2
S12000 M3
(entity teardrop: path, degree 3, 2D)
G0 Z5.
X0. Y0.
G1 Z-1. F300.
G3 X8.7198 Y4.7333 I-61.4901 J123.6771 F1000.
G3 X15.3561 Y9.0401 I-47.4214 J80.3374
G3 X20.4736 Y13.0946 I-36.4316 J51.24
G3 X24.3259 Y16.953 I-28.0703 J31.8783
G3 X27.1374 Y20.733 I-21.9134 J19.2344
G3 X29.0475 Y24.6546 I-17.5818 J10.9896
G3 X30. Y30. I-14.9526 J5.422
G3 X29.4418 Y33.8846 I-13.3484 J0.0643
G3 X24.2293 Y40.3713 I-10.5723 J-3.1579
G3 X20.2999 Y41.7512 I-5.9958 J-10.789
G3 X15.5146 Y41.7841 I-2.4937 J-14.6853
G3 X10. Y40. I2.8258 J-18.1492
G3 X4.1716 Y35.8511 I11.0674 J-21.7159
G3 X-1.8166 Y27.3219 I18.8562 J-19.6053
G3 X-3.7855 Y20.6686 I24.1376 J-10.761
G3 X-3.9258 Y12.5593 I28.9615 J-4.5569
G3 X-2.4251 Y5.8605 I34.4997 J4.2113
G3 X0. Y0. I41.2574 J13.6405
G0 Z5.
M5
M30
%
