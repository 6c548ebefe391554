// atmosphere.pov -- sky_sphere with a gradient colour map, fog (constant)
// and ground fog (fog_type 2), background hidden by the sky_sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1, 10> angle 60 }
background { color rgb <1, 0, 1> }
sky_sphere { pigment { gradient y color_map { [0 color rgb <0.9, 0.85, 0.7>] [0.3 color rgb <0.4, 0.6, 0.95>] [1 color rgb <0.1, 0.2, 0.6>] } } }
fog { fog_type 2 distance 12 color rgb <0.85, 0.85, 0.9> fog_offset 0.3 fog_alt 0.6 }
fog { distance 120 color rgbt <0.7, 0.75, 0.85, 0.2> }
light_source { <-20, 30, -20> color rgb 1 }

plane { y, 0 pigment { checker color rgb <0.3, 0.6, 0.3> color rgb <0.2, 0.4, 0.2> scale 2 } }
#declare I = 0;
#while (I < 8)
  cylinder { <0, 0, 0>, <0, 3, 0>, 0.4 pigment { color rgb <0.9, 0.4, 0.3> } translate <-3 + mod(I, 2)*6, 0, I*5> }
  #declare I = I + 1;
#end
