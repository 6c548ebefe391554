#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,5,-6> look_at <0,0,0> }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0,4,0>, rgb 1 spotlight point_at <0,0,1.5> radius 15 falloff 30 tightness 5 }
light_source { <-3,3,-1>, rgb <1,0.5,0.2> spotlight point_at <-2,0,2> radius 10 falloff 25 }
