// quadrics_torus.pov -- cylinder (open and closed), cone, disc, torus.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 48 }
background { color rgb <0.6, 0.7, 0.85> }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <6, 6, -6> color rgb 0.3 }

plane { y, 0 pigment { color rgb <0.75, 0.72, 0.65> } }
cylinder { <-2.6, 0, 0>, <-2.6, 2, 0>, 0.6
  pigment { color rgb <0.85, 0.25, 0.2> } finish { phong 0.6 } }
cylinder { <-1.6, 0.3, -1.6>, <-0.4, 0.3, -2.0>, 0.3 open
  pigment { color rgb <0.9, 0.9, 0.3> } }
cone { <0, 0, 0>, 0.8, <0, 2.2, 0>, 0.1
  pigment { color rgb <0.2, 0.5, 0.9> } finish { specular 0.4 } }
cone { <1.3, 0.25, -1.8>, 0.25, <2.1, 0.25, -1.5>, 0.05 open
  pigment { color rgb <0.9, 0.5, 0.9> } }
torus { 0.9, 0.3 rotate x*-60 translate <2.4, 1.2, 0.5>
  pigment { color rgb <0.3, 0.85, 0.4> } finish { phong 0.8 phong_size 60 } }
disc { <0, 0.01, -2>, y, 0.7, 0.3 pigment { color rgb <0.1, 0.1, 0.1> } }
disc { <-2.6, 2.8, 1.5>, <0, -0.5, -1>, 0.6 pigment { color rgb <0.95, 0.6, 0.2> } }
