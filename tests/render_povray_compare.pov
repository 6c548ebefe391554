#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
background { rgb <0.3, 0.5, 0.9> }
camera { location <0, 2, -6> direction <0, -0.45, 1.5> right x*4/3 up y }
light_source { <-4, 6, -3>, rgb <1, 0.9, 0.8> }
light_source { <3, 5, -1>, rgb 0.4 parallel point_at <0, 0, 0> }
plane { y, -1 pigment { checker rgb 1, rgb <0.1, 0.2, 0.6> scale 0.75 } finish { ambient 0.1 diffuse 0.6 } }
sphere { <-1.5, 0, 2>, 1 pigment { rgb <0.9, 0.5, 0.2> } finish { ambient 0.1 diffuse 0.5 phong 0.8 phong_size 30 metallic 0.7 reflection { 0.2, 0.8 falloff 2 metallic 1 } } }
sphere { 0, 1 scale <0.5, 1, 0.5> rotate <0, 0, 30> translate <1.5, 0, 1.5> pigment { rgb <0.2, 0.8, 0.3> } finish { specular 0.6 roughness 0.02 brilliance 2 } }
box { <-0.5, -1, -0.5>, <0.5, 0.2, 0.5> rotate <0, 35, 0> translate <0.3, 0, 4> pigment { rgb <0.8, 0.2, 0.2> } finish { ambient 0.2 diffuse 0.7 reflection 0.3 } }
triangle { <-3, -1, 5>, <-1, 2.5, 6>, <1, -1, 6.5> pigment { rgb <0.9, 0.9, 0.3> } }
union {
  sphere { <0, 0, 0>, 0.4 translate x*0.6 }
  sphere { <0, 0, 0>, 0.4 translate -x*0.6 pigment { rgb <1, 0, 1> } }
  pigment { checker rgb <0, 1, 1>, rgb <1, 1, 0> scale 0.3 }
  translate <-0.2, -0.6, 0.5>
}
sphere { <2.5, 1.5, 3>, 0.6 pigment { rgb 1 } no_shadow }
