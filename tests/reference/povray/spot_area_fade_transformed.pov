#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,6,-6> look_at <0,0,0> }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-0.5,0,-0.5>, <0.5,1.5,0.5> pigment { rgb <1,0.3,0.2> } }
light_source { <0,5,0>, rgb 1 spotlight point_at <0.5,0,0> radius 20 falloff 35 tightness 3 area_light <2,0,0>, <0,0,2>, 5, 5 adaptive 1 fade_distance 4 fade_power 1 rotate 20*z translate <0.5,0,-0.5> }
light_source { <-4,3,-2>, rgb 0.3 parallel point_at 0 }
