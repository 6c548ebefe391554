// camera_ultra_wide.pov -- ultra_wide_angle camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { ultra_wide_angle location <0, 1.5, -2.8> look_at <0, 1, 5> angle 160 }
#include "camera_scene.inc"
