#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.1,0.1,0.2> }
plane { y, -1 pigment { checker rgb 1, rgb <0.2,0.3,0.5> } }
sphere { <0,0,3>, 1 pigment { rgb <1,0.3,0.2> } }
sphere { <3,0,0>, 1 pigment { rgb <0.2,1,0.3> } }
sphere { <-3,0,0>, 1 pigment { rgb <0.2,0.3,1> } }
sphere { <0,0,-3>, 1 pigment { rgb <1,1,0.2> } }
sphere { <0,3,0>, 1 pigment { rgb <1,0.2,1> } }
sphere { <2,1.5,3>, 0.5 pigment { rgb <0.2,1,1> } }
light_source { <5,10,-5>, rgb 1 }
camera { ultra_wide_angle location <0,0,0> look_at <0,0,3> angle 200 }
