%
(a chain of G5 moves: lines 9, 10 and 12 take their start tangent from the G5 before them)
G21 G90 G17
T1 M6
S10000 M3
G0 Z5.
X0. Y0.
G1 Z-1. F300.
G5 X10. Y0. I3. J3. P-3. Q3. F900.
G5 X20. Y0. P-3. Q-3.
G5 X30. Y0. P-3. Q3.
G5 X40. Y0. I2. J2. P-3. Q-3.
G5 X50. Y0. P-3. Q3.
G1 Y10.
G0 Z5.
M5
M30
%
