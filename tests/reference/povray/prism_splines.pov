// prism: the four spline types with linear_sweep (front) and conic_sweep (back; open, and cut by a difference).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 9, -13> look_at <0, 0.3, 1> angle 48 }
light_source { <-8, 14, -10> color rgb 1 }
light_source { <10, 6, -4> color rgb 0.4 }
background { rgb <0.15, 0.2, 0.3> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.55 } }
#declare Lin = prism { linear_spline 0, 1, 11,
  <1,0>, <0.31,0.22>, <0.31,0.95>, <-0.12,0.36>, <-0.81,0.59>, <-0.38,0>, <-0.81,-0.59>, <-0.12,-0.36>, <0.31,-0.95>, <0.31,-0.22>, <1,0> }
#declare Quad = prism { quadratic_spline 0, 1, 7, <0,-1>, <1,0>, <0,1>, <-1,0.2>, <-0.4,-0.9>, <0.5,-0.8>, <1,0> }
#declare Cub = prism { cubic_spline 0, 1, 8, <0.5,-0.9>, <1,0>, <0.2,0.9>, <-0.9,0.4>, <-0.6,-0.8>, <0.5,-0.9>, <1,0>, <0.2,0.9> }
#declare Bez = prism { bezier_spline 0, 1, 12,
  <1,0>, <1,0.8>, <0.2,1>, <0,0.5>,  <0,0.5>, <-0.2,1>, <-1,0.8>, <-1,0>,  <-1,0>, <-1,-1>, <1,-1>, <1,0>
  }
#declare T = texture { pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
object { Lin texture { T } scale <1.2,1,1.2> translate <-4.5, 0, -1.5> }
object { Quad texture { T } scale <1.2,1,1.2> translate <-1.5, 0, -1.5> }
object { Cub texture { T } scale <1.2,1,1.2> translate <1.5, 0, -1.5> }
object { Bez texture { T } scale <1.2,1,1.2> translate <4.5, 0, -1.5> }
#declare C = texture { pigment { rgb <0.3, 0.6, 0.9> } finish { phong 0.6 } }
prism { conic_sweep linear_spline 0, 1, 11,
  <1,0>, <0.31,0.22>, <0.31,0.95>, <-0.12,0.36>, <-0.81,0.59>, <-0.38,0>, <-0.81,-0.59>, <-0.12,-0.36>, <0.31,-0.95>, <0.31,-0.22>, <1,0>
  texture { C } rotate 180*x translate y scale <1.2,1.6,1.2> translate <-4.5, 0, 2.5> }
prism { conic_sweep quadratic_spline 0.3, 1, 7, <0,-1>, <1,0>, <0,1>, <-1,0.2>, <-0.4,-0.9>, <0.5,-0.8>, <1,0>
  texture { C } rotate 180*x translate y scale <1.2,1.6,1.2> translate <-1.5, 0, 2.5> }
prism { conic_sweep cubic_spline 0, 1, 8, <0.5,-0.9>, <1,0>, <0.2,0.9>, <-0.9,0.4>, <-0.6,-0.8>, <0.5,-0.9>, <1,0>, <0.2,0.9>
  open texture { C } rotate 180*x translate y scale <1.2,1.6,1.2> translate <1.5, 0, 2.5> }
difference {
  prism { conic_sweep bezier_spline 0.2, 1, 12,
    <1,0>, <1,0.8>, <0.2,1>, <0,0.5>,  <0,0.5>, <-0.2,1>, <-1,0.8>, <-1,0>,  <-1,0>, <-1,-1>, <1,-1>, <1,0>
    rotate 180*x translate y scale <1.2,1.6,1.2> }
  sphere { <0, 1.6, 0>, 0.6 }
  texture { C } translate <4.5, 0, 2.5> }
