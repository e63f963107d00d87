%
(bezcam 0.1.0: curve-helix-xz.json, machine linuxcnc, output arcs)
(tolerance 0.01 mm; largest deviation measured 0.009955 mm, proven bound 0.009994 mm, rounding included)
(T3: groove-xz, arch-yz)
(T3 plunge feed 200 mm/min)
(estimated cycle time 11 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 6.42 s; the exact path's bound on this machine 6.30 s [x1.020; rapids, plunges and pauses not counted])
(order shortest: 0 nested contours cut before what encloses them; rapids 30 mm in XY instead of 38.3 mm as written [8.3 mm saved])
G21 G90 G17
G40 G49 G80 G94
G54
G53 G0 Z0
T3 M6
G43 H3
S12000 M3
(entity groove-xz: path, degree 3, 3D)
G0 Z5.
X-10. Y0.
G1 Z0. F200.
G18
G2 X-9.6425 Y1.6673 Z-2.6594 I10.0149 K-0.0076 F600.
G2 X-7.6119 Y4.4809 Z-6.4856 I9.6172 K2.6519
G2 X-3.1411 Y8.0132 Z-9.4967 I7.6211 K6.4911
G2 X-0.3681 Y9.7768 Z-9.9933 I3.1276 K9.4737
G1 X0. Y10. Z-10.
G2 X2.661 Y11.6684 Z-9.6421 I0.0076 K10.0148
G2 X6.4889 Y14.4837 Z-7.6091 I-2.6536 K9.6169
G2 X9.4774 Y17.9743 Z-3.199 I-6.4952 K7.619
G2 X9.9915 Y19.7478 Z-0.4159 I-9.4506 K3.1847
G1 X10. Y20. Z0.
G0 Z5.
(entity arch-yz: bezier, degree 3, 3D)
X30.
G1 Z0. F200.
G19
G2 Y18.3142 Z-3.5207 J-4.6199 K0.0482 F600.
G2 Y14.9181 Z-5.3019 J-5.9302 K7.1786
G2 Y4.8775 Z-5.2369 J-4.9124 K16.7112
G2 Y1.5727 Z-3.4191 J2.5805 K8.6044
G2 Y0. Z0. J3.0087 K3.4552
G0 Z5.
G17
M5
M30
%
