%
(bezcam 0.1.0: job-two-tools.json, machine generic, output arcs)
(program 4711)
(tolerance 0.01 mm; largest deviation measured 0.009894 mm, proven bound 0.009982 mm, rounding included)
(T1: pocket-outline)
(T2: engraving)
(estimated cycle time 16 s: feeds as programmed, rapids at 20000 mm/min, no acceleration, tool changes not counted)
G21 G90 G17
G40 G49 G80 G94
T1 M06
S10000 M03
M08
(entity pocket-outline: path, degree 3, 2D)
G00 Z5.
X0. Y0.
Z1.
G01 Z-1. F250.
X40. F900.
G03 X46.068 Y1.728 I0.189 J10.855
G03 X50.153 Y6.836 I-6.304 J9.229
G03 X49.856 Y18.827 I-13.902 J5.655
G03 X45.245 Y23.762 I-9.799 J-4.534
G03 X40. Y25. I-5.092 J-9.844
G01 X0.
G03 X-6.111 Y23.243 I-0.19 J-10.845
G03 X-10.16 Y18.148 I6.361 J-9.211
G03 X-9.875 Y6.213 I13.916 J-5.639
G03 X-5.339 Y1.289 I9.84 J4.513
G03 X0. Y0. I5.183 J9.766
G00 Z5.
M09
M05
T2 M06
S18000 M03
M07
(entity engraving: bezier, degree 3, 2D)
X5. Y12.5
Z1.
G01 Z-0.2 F250.
G02 X8.891 Y14.883 I6.986 J-7.038 F400.
G02 X13.512 Y15.005 I2.545 J-8.821
G02 X17.849 Y13.5 I-4.905 J-21.139
G03 X22.444 Y11.37 I304.446 J650.509
G03 X26.742 Y9.945 I8.448 J18.283
G03 X31.782 Y10.356 I1.83 J8.666
G03 X35. Y12.5 I-4.023 J9.525
G00 Z5.
M09
M05
M30
%
