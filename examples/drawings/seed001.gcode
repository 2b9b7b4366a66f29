; seed 001's drawing task: three straight lines and a circle (pen by Z)
; units mm, absolute; the pen is down at Z <= 0
G21 G90 G17
G0 Z5 (pen up)
G0 X10 Y10
G1 Z0 F300 (pen down)
G1 X70 Y10 F1200 ; horizontal
G0 Z5
G0 X10 Y20
G1 Z0
G1 X10 Y80 ; vertical
G0 Z5
G0 X20 Y20
G1 Z0
G1 X70 Y70 ; diagonal
G0 Z5
G0 X120 Y50
G1 Z0
G2 X120 Y50 I-25 J0 ; circle of radius 25 mm around (95, 50), clockwise
G0 Z5
G4 P0.5 (let the ink settle)
G28 (home)
M2
