// `cylinder 1` camera (angle 120) around an asymmetric scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { cylinder 1 location <0, 1.5, -4> look_at <0, 1, 0> angle 120 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <1.5, 1, 0>, 1 pigment { rgb <1, 0.2, 0.1> } }
box { <-3, 0, -1>, <-1, 3, 1> pigment { rgb <0.2, 0.4, 1> } }
cylinder { <0, 0, 2>, <0, 4, 2>, 0.3 pigment { rgb <0.2, 0.9, 0.3> } }
