// `up z` with the default `direction z` (up × direction = 0) and look_at: POV-Ray 3.7
// mirrors the picture (as in its objects/prism3 scenes). Asymmetric scene.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-10, 10, -10> right x*4/3 up z look_at <0, 0, 0> angle 30 }
light_source { <-30, 40, -20> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
sphere { <2, 1, 0>, 1 pigment { rgb <1, 0.2, 0.1> } }
box { <-3, 0, -1>, <-1, 3, 1> pigment { rgb <0.2, 0.4, 1> } }
