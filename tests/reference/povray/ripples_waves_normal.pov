// ripples and waves as normals: one and three centres (number_of_waves),
// frequency, phase and scale on a plane and on spheres.
#version 3.7;
global_settings { assumed_gamma 1.0 number_of_waves 3 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 60 }
light_source { <-6, 10, -4> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } normal { ripples 0.6 frequency 0.8 scale 1.3 } finish { phong 0.4 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb <0.9, 0.6, 0.4> } normal { waves 0.7 frequency 3 phase 0.1 } finish { phong 0.7 } }
sphere { <1.6, 1, 0>, 1 pigment { rgb <0.5, 0.7, 0.9> } normal { ripples 0.4 frequency 4 scale <1, 2, 1> } finish { phong 0.7 } }
