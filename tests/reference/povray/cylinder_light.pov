#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,5,-6> look_at <0,0,0> }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0,4,-3>, rgb 1 cylinder point_at <0,0,2> radius 0.7 falloff 1.5 tightness 2 }
light_source { <3,3,0>, rgb <0.2,0.5,1> cylinder point_at <1,0,0> }
