// camera_orthographic.pov -- orthographic camera (view size from right/up).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <6, 8, -10> look_at <0, 0.8, 0> right x*12 up y*9 }
#include "camera_scene.inc"
