#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,3,-6> look_at <0,1,0> }
plane { y, 0 pigment { rgb 1 } }
sphere { <1,0.5,0>, 0.5 pigment { rgb 1 } }
light_source { <3,4,-3>, rgb 0.5 spotlight point_at 0 radius 10 falloff 20 shadowless }
