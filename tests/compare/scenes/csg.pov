// csg.pov -- union, merge, intersection, difference, clipped_by, inverse.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 50 }
background { color rgb <0.6, 0.7, 0.85> }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <7, 6, -5> color rgb 0.3 }

plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.55 } }
// difference: a box with a sphere carved out
difference {
  box { -1, 1 }
  sphere { 0, 1.3 }
  pigment { color rgb <0.9, 0.3, 0.25> }
  translate <-3, 1, 0>
}
// intersection: a lens
intersection {
  sphere { <0, 0, -0.6>, 1.2 }
  sphere { <0, 0, 0.6>, 1.2 }
  pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.6 }
  rotate y*40 translate <-0.2, 1.1, 0>
}
// merge of two translucent spheres (no inner surfaces)
merge {
  sphere { <-0.4, 0, 0>, 0.7 }
  sphere { <0.4, 0, 0>, 0.7 }
  pigment { color rgbt <0.4, 0.95, 0.4, 0.5> }
  translate <2.2, 0.7, -0.4>
}
// union of the same, for comparison
union {
  sphere { <-0.4, 0, 0>, 0.5 }
  sphere { <0.4, 0, 0>, 0.5 }
  pigment { color rgb <0.95, 0.8, 0.3> }
  translate <1.0, 0.5, -2.5>
}
// clipped_by: a sphere cut by a plane, open
sphere { 0, 0.9
  clipped_by { plane { y, 0.3 } }
  pigment { color rgb <0.9, 0.5, 0.9> }
  translate <-1.5, 0.9, -2.4>
}
// inverse: a box minus an inverted sphere = box intersect sphere
intersection {
  box { -0.8, 0.8 }
  object { sphere { 0, 1.05 } inverse }
  pigment { color rgb <0.3, 0.85, 0.85> }
  rotate y*25 translate <3.2, 0.8, 1.8>
}
