#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,1,-6> look_at <0,1,0> angle 90 }
background { rgb <0.2,0.3,0.8> }
sky_sphere { pigment { checker rgb <0.2,0.4,1>, rgb 1 scale 0.2 } pigment { checker rgbft <1,0,0,0.3,0.4>, rgbt <0,1,0,0.5> scale 0.3 rotate 20*x } rotate <0,30,20> }
plane { y, 0 pigment { rgb 0.5 } }
light_source { <5,10,-5>, rgb 1 }
