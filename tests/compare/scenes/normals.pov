// normals.pov -- bumps, dents, ripples, waves, wrinkles on spheres, and a
// rippled floor. bumps, dents and wrinkles use POV-Ray's noise: pixel
// equality is not expected there.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.8, 0> angle 50 }
background { color rgb <0.6, 0.7, 0.85> }
light_source { <-6, 10, -8> color rgb 1 }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.75> } normal { ripples 0.4 scale 0.8 } finish { phong 0.3 } }
#declare T = texture { pigment { color rgb <0.85, 0.55, 0.35> } finish { phong 0.8 phong_size 40 } }
sphere { <-3.2, 1, 0>, 0.9 texture { T normal { bumps 0.6 scale 0.15 } } }
sphere { <-1.1, 1, 0>, 0.9 texture { T normal { dents 0.8 scale 0.2 } } }
sphere { < 1.0, 1, 0>, 0.9 texture { T normal { waves 0.5 frequency 3 } } }
sphere { < 3.1, 1, 0>, 0.9 texture { T normal { wrinkles 0.7 scale 0.3 } } }
sphere { < 0, 0.6, -2.4>, 0.6 texture { T normal { ripples 0.8 scale 0.3 } } }
