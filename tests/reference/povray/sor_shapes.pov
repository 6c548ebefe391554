// sor: closed (caps) and open, uneven heights (the slopes are 2 r dr/dh from the neighbours),
// a first pair of points at one height (accepted, as in POV-Ray's sor1.pov), scaled and rotated.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -10> color rgb 1 }
light_source { <-8, 3, -3> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 } }
sor { 5, <0,-1>, <1,0>, <1.4,1>, <0.6,2>, <0,3> pigment { rgb <0.6, 0.6, 1> } translate <-2.6, -1, 0> }
sor { 6, <0.5,-1>, <1,0>, <0.4,0.5>, <1.2,1.5>, <0.8, 2>, <0,2.2> open pigment { rgb <1, 0.6, 0.6> } finish { phong 0.5 } translate <0, -1, 0> }
sor { 7, <0,0>, <0.3,0>, <0.9,0.5>, <0.7,1.2>, <0.3,1.6>, <0.5,2.2>, <0.6,2.4> sturm
  pigment { rgb <0.5, 1, 0.6> } rotate <0, 0, 25> scale 1.2 translate <2.5, -1, 0.5> }
