// lathe and sor in CSG: a sor minus a closed lathe outline, an open lathe outline cut by a box
// (POV-Ray's inside rule: at least the smallest radius and an odd number of crossings), and
// an open sor (still a solid inside) cut by a sphere.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -8> look_at <0, 1, 0> angle 50 }
light_source { <5, 10, -10> color rgb 1 }
light_source { <-8, 3, -3> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 } }
difference {
  sor { 6, <0,-1>, <1,0>, <1.3,1>, <0.9,2>, <1.1,2.6>, <0,3> }
  lathe { linear_spline 5, <0.5,0.3>, <1,1>, <0.9,2>, <1,3>, <0.5, 0.3> }
  pigment { rgb <0.6, 0.7, 1> } translate <-2.8, -1, 0>
}
intersection {
  lathe { quadratic_spline 5, <1,-1>, <0.5,0>, <1.5,1>, <1.2,2>, <1.4,2.5> }
  box { <-2, -1, -2>, <2, 3, 0> }
  pigment { rgb <1, 1, 0.5> } translate <0, -1, 0.5>
}
difference {
  sor { 5, <0,-1>, <1,0>, <1.4,1>, <0.6,2>, <0,3> open }
  sphere { <0, 1, -1.2>, 0.9 }
  pigment { rgb <1, 0.5, 0.4> } translate <2.8, -1, 0>
}
