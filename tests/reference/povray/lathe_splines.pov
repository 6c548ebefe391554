// lathe: the four spline types (quadratic and cubic with their control points, bezier with a
// kink, sturm accepted), one tilted, over a checker floor.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -9> look_at <0, 1, 0> angle 52 }
light_source { <5, 10, -10> color rgb 1 }
light_source { <-8, 3, -3> color rgb 0.4 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.5 } }
#declare T = finish { phong 0.5 }
lathe { linear_spline 5, <0.3,-1>, <1,-0.5>, <0.6,0.5>, <1.1,1.5>, <0.2,2> pigment { rgb <0.9, 0.9, 0.3> } finish { T } translate <-4.5, 0, 1> }
lathe { quadratic_spline 6, <0,-1>, <1,0>, <1.5,0.8>, <0.5,1.4>, <1.2,2>, <0.2, 2.5> pigment { rgb <1, 0.6, 0.2> } finish { T } translate <-2.5, -1, 0> }
lathe { bezier_spline 8, <0.2,0>, <2,0.1>, <1.5,1>, <0.8,1.2>, <0.8,1.2>, <0.2,1.4>, <1.5,2.2>, <1,2.5> sturm pigment { rgb <0.3, 0.9, 0.4> } finish { T } translate <0.5, -1, 0> }
lathe { cubic_spline 6, <0,-1>, <1,0>, <0.5,1>, <1.2,1.8>, <0.3,2.5>, <0, 3> pigment { rgb <0.9, 0.4, 0.9> } finish { T } rotate <30, 0, 20> translate <3.5, -0.5, 0> }
