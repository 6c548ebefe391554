// glass.pov -- refraction with ior, filter and transmit, interior fade
// (fade_distance, fade_power, fade_color), a hollow glass shell.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -8> look_at <0, 0.8, 0> angle 50 }
background { color rgb <0.55, 0.65, 0.85> }
light_source { <-6, 9, -8> color rgb 1 }

plane { y, 0 pigment { checker color rgb 0.95 color rgb <0.8, 0.2, 0.2> scale 0.6 } }
plane { z, 4 pigment { checker color rgb 0.95 color rgb <0.2, 0.3, 0.8> scale 0.6 } }
sphere { <-2.5, 1, 0>, 1
  pigment { color rgbf <1, 1, 1, 0.95> } finish { phong 0.9 phong_size 80 reflection 0.05 }
  interior { ior 1.5 } }
sphere { <0, 1, 0>, 1
  pigment { color rgbf <0.4, 0.9, 0.5, 0.85> } finish { phong 0.9 phong_size 80 }
  interior { ior 1.33 } }
box { <-0.9, 0, -0.9>, <0.9, 1.8, 0.9> rotate y*30 translate <2.5, 0, 0>
  pigment { color rgbt <1, 1, 1, 0.9> } finish { specular 0.5 }
  interior { ior 1.45 fade_distance 0.8 fade_power 2 fade_color <0.2, 0.4, 0.9> } }
sphere { <-0.8, 0.5, -2.5>, 0.5 hollow
  pigment { color rgbt <0.9, 0.8, 0.3, 0.6> } interior { ior 1.0 } }
