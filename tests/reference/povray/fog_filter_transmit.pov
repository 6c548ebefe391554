#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,2,-6> look_at <0,1,0> }
background { rgb <0.2,0.3,0.8> }
plane { y, 0 pigment { checker rgb 1, rgb 0.2 } }
sphere { <0,1,2>, 1 pigment { rgb <1,0.3,0.2> } }
sphere { <2,1,10>, 1 pigment { rgb <0.3,1,0.2> } }
light_source { <5,10,-5>, rgb 1 }
fog { distance 8 color rgbft <0.9,0.5,0.2,0.3,0.2> }
