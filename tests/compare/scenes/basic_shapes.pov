// basic_shapes.pov -- sphere, box, plane, triangle, union, checker, point and
// parallel lights: what rts had before the classic renderer (issue 3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.6, 0> angle 50 }
background { color rgb <0.55, 0.65, 0.85> }
light_source { <-6, 9, -7> color rgb 1 }
light_source { <5, 8, -2> color rgb <0.25, 0.25, 0.3> parallel point_at <0, 0, 0> }

plane { y, 0
  pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.15, 0.25, 0.5> scale 0.8 }
  finish { ambient 0.1 diffuse 0.7 }
}
sphere { <-1.8, 1, 0.5>, 1
  pigment { color rgb <0.9, 0.3, 0.2> }
  finish { phong 0.7 phong_size 40 reflection 0.15 }
}
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6>
  rotate y*30 translate <0.6, 0, -0.8>
  pigment { color rgb <0.3, 0.8, 0.35> }
  finish { specular 0.5 roughness 0.02 }
}
union {
  triangle { <1.6, 0, 1>, <3.2, 0, 1>, <2.4, 2.2, 1.6> }
  triangle { <1.6, 0, 1>, <2.4, 0, 2.4>, <2.4, 2.2, 1.6> }
  pigment { color rgb <0.95, 0.8, 0.3> }
  finish { ambient 0.15 diffuse 0.8 }
}
sphere { <0.2, 0.4, 1.8>, 0.4 pigment { color rgb <0.8, 0.8, 0.95> } finish { reflection 0.5 } }
