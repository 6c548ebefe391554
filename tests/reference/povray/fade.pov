#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,5,-6> look_at <0,0,0> }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
light_source { <0,2,0>, rgb 1 fade_distance 2 fade_power 2 }
light_source { <3,1,3>, rgb <1,0,0> fade_distance 1 fade_power 1 }
