// finish.pov -- ambient, diffuse, brilliance, phong, specular/roughness,
// metallic, reflection (plain, variable with falloff, fresnel with ior).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 2.5, -8> look_at <0, 0.8, 0> angle 50 }
background { color rgb <0.55, 0.65, 0.85> }
light_source { <-6, 9, -8> color rgb 1 }
light_source { <6, 6, -5> color rgb 0.3 }

plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.5> } finish { reflection 0.1 } }
sphere { <-3, 1, 0>, 0.9 pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0.05 diffuse 0.9 brilliance 3 phong 0.9 phong_size 80 } }
sphere { <-1, 1, 0>, 0.9 pigment { color rgb <0.3, 0.8, 0.3> } finish { specular 0.8 roughness 0.01 } }
sphere { < 1, 1, 0>, 0.9 pigment { color rgb <0.9, 0.7, 0.2> } finish { ambient 0 diffuse 0.3 phong 1 metallic reflection { 0.6 metallic } } }
sphere { < 3, 1, 0>, 0.9 pigment { color rgb <0.1, 0.1, 0.2> } finish { ambient 0 diffuse 0.6 specular 0.6 roughness 0.02 reflection { 0.0, 1.0 fresnel on } conserve_energy }
  interior { ior 1.5 } }
sphere { < 0, 0.5, -2.5>, 0.5 pigment { color rgb <0.8, 0.8, 0.9> } finish { reflection { 0.1, 0.9 falloff 3 } } }
