%
(bezcam 0.1.0: job-two-tools.json, machine generic, output lines)
(program 4711)
(tolerance 0.01 mm; largest deviation measured 0.009438 mm, proven bound 0.009806 mm, rounding included)
(T2: engraving)
(T1: pocket-outline)
(T2 plunge feed 250 mm/min)
(T1 plunge feed 250 mm/min)
(estimated cycle time 31 s on the motion model of machine generic [acceleration, corners, tool changes])
(cutting along the curves 15.27 s; the exact path's bound on this machine 15.23 s [x1.002; rapids, plunges and pauses not counted])
(order shortest: 1 nested contour cut before what encloses them; rapids 26.9 mm in XY instead of 13.5 mm as written [13.5 mm more: nested contours first, one tool at a time])
G21 G90 G17
G40 G49 G80 G94
T2 M06
S18000 M03
M07
(entity engraving: bezier, degree 3, 2D)
G00 Z5.
X5. Y12.5
Z1.
G01 Z-0.2 F250.
X5.819 Y13.227 F400.
X6.775 Y13.909
X7.732 Y14.439
X8.699 Y14.831
X9.688 Y15.092
X10.715 Y15.229
X11.798 Y15.24
X12.961 Y15.116
X14.233 Y14.844
X15.695 Y14.386
X17.498 Y13.665
X20. Y12.5
X22.502 Y11.335
X24.305 Y10.614
X25.767 Y10.156
X27.039 Y9.884
X28.202 Y9.76
X29.285 Y9.771
X30.312 Y9.908
X31.301 Y10.169
X32.268 Y10.561
X33.225 Y11.091
X34.181 Y11.773
X35. Y12.5
G00 Z5.
M09
M05
T1 M06
S10000 M03
M08
(entity pocket-outline: path, degree 3, 2D)
X40. Y0.
Z1.
G01 Z-1. F250.
X41.122 Y0.039 F900.
X42.361 Y0.214
X43.527 Y0.51
X44.623 Y0.925
X45.65 Y1.456
X46.608 Y2.101
X47.495 Y2.86
X48.308 Y3.733
X49.04 Y4.718
X49.684 Y5.81
X50.232 Y7.007
X50.673 Y8.293
X50.995 Y9.651
X51.193 Y11.062
X51.259 Y12.5
X51.193 Y13.938
X50.995 Y15.349
X50.673 Y16.707
X50.232 Y17.993
X49.684 Y19.19
X49.04 Y20.282
X48.308 Y21.267
X47.495 Y22.14
X46.608 Y22.899
X45.65 Y23.544
X44.623 Y24.075
X43.527 Y24.49
X42.361 Y24.786
X41.122 Y24.961
X40. Y25.
X0.
X-1.122 Y24.961
X-2.361 Y24.786
X-3.527 Y24.49
X-4.623 Y24.075
X-5.65 Y23.544
X-6.608 Y22.899
X-7.495 Y22.14
X-8.308 Y21.267
X-9.04 Y20.282
X-9.684 Y19.19
X-10.232 Y17.993
X-10.673 Y16.707
X-10.995 Y15.349
X-11.193 Y13.938
X-11.259 Y12.5
X-11.193 Y11.062
X-10.995 Y9.651
X-10.673 Y8.293
X-10.232 Y7.007
X-9.684 Y5.81
X-9.04 Y4.718
X-8.308 Y3.733
X-7.495 Y2.86
X-6.608 Y2.101
X-5.65 Y1.456
X-4.623 Y0.925
X-3.527 Y0.51
X-2.361 Y0.214
X-1.122 Y0.039
X0. Y0.
X40.
G00 Z5.
M09
M05
M30
%
