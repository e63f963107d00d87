%
(bezcam 0.1.0: path-closed-teardrop.json, machine linuxcnc, output arcs)
(tolerance 0.01 mm; largest deviation measured 0.009956 mm, proven bound 0.009963 mm, rounding included)
(T2: teardrop)
(estimated cycle time 9 s on the motion model of machine linuxcnc [acceleration, corners, tool changes])
(cutting along the curves 7.08 s; the exact path's bound on this machine 7.05 s [x1.003; rapids, plunges and pauses not counted])
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
G3 X13.2046 Y7.5531 I-54.0976 J109.8941 F1000.
G3 X21.7278 Y14.2467 I-34.9458 J53.271
G3 X27.0032 Y20.5182 I-22.8749 J24.5962
G3 X29.7178 Y27.0906 I-16.0842 J10.4901
G3 X30. Y30. I-14.9762 J2.9209
G3 X28.2609 Y36.5176 I-12.3687 J0.1905
G3 X21.425 Y41.5028 I-9.6226 J-6.0155
G3 X13.9828 Y41.4801 I-3.6768 J-14.5198
G3 X10. Y40. I4.6444 J-18.5963
G3 X1.3239 Y32.6531 I11.5191 J-22.3994
G3 X-4.1122 Y14.8299 I21.8246 J-16.3971
G3 X-1.6532 Y3.71 I34.8206 J1.8682
G3 X0. Y0. I41.5876 J16.3089
G0 Z5.
M5
M30
%
