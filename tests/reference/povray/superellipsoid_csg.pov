// superellipsoid in CSG: a difference with a sphere, an intersection with a box,
// and a merge of two.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <3, 5, -7> look_at <0, 0, 0> angle 50 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.3 } }
difference {
  superellipsoid { <0.4, 0.8> }
  sphere { <0, 1, -0.3>, 0.8 }
  pigment { rgb <1, 0.9, 0.3> }
  finish { phong 0.6 }
  scale 0.8 translate <-1.2, 0, -2>
}
intersection {
  superellipsoid { <0.1, 2> }
  box { <-2, -2, -2>, <2, 0.5, 2> }
  pigment { rgb <0.9, 0.5, 1> }
  scale 0.7 rotate y*30 translate <1.3, 0, -2.2>
}
merge {
  superellipsoid { <0.2, 0.2> scale <1.5, 0.4, 0.4> }
  superellipsoid { <1, 0.2> scale <0.6, 1, 0.6> }
  pigment { rgb <0.3, 0.7, 1> }
  translate <0, 0, 1>
}
