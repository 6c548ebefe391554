#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,10,0> look_at <0,0,0> }
plane { y, 0 pigment { checker rgb 1, rgb <0.2,0.3,0.5> } }
sphere { <2,0,1>, 1 pigment { rgb <1,0.3,0.2> } }
sphere { <-1,0,3>, 1 pigment { rgb <0.2,1,0.3> } }
light_source { <5,10,-5>, rgb 1 }
