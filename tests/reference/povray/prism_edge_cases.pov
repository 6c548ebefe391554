// prism edge cases POV-Ray and rts agree on: an open linear outline closed for you,
// heights in falling order, a conic sweep through y = 0 (negative heights mirror the
// outline), an open prism that still counts as solid in an intersection.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 9, -10> look_at <0, 0.5, 0> angle 40 }
light_source { <10, 20, -10> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
prism { linear_spline 0, 1, 4, <-1,-1>, <1,-1>, <0,1>, <0.5,1.5> pigment { rgb <1,0.6,0.3> } translate <-3, 0, 2> }
prism { linear_spline 1, 0, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> pigment { rgb <0.6,1,0.3> } translate <0, 0, 2> }
prism { conic_sweep linear_spline 1, -0.5, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> pigment { rgb <0.3,0.6,1> } translate <3, 0.5, 2> }
intersection {
  prism { linear_spline 0, 1, 5, <-1.5,-1.5>, <1.5,-1.5>, <1.5,1.5>, <-1.5,1.5>, <-1.5,-1.5> open pigment { rgb 1 } }
  sphere { 0, 1.9 pigment { rgb <1,0,0> } }
  translate <0, 0, -2>
}
