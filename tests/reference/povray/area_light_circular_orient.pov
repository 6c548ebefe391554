#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,6,-6> look_at <0,0,0> }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-0.5,0,-0.5>, <0.5,1.5,0.5> pigment { rgb <1,0.3,0.2> } }
sphere { <-2,1,1>, 0.7 pigment { rgb <0.2,0.4,1> } }
light_source { <2,5,-1>, rgb 1 area_light <3,0,0>, <0,0,3>, 5,5 circular orient }
