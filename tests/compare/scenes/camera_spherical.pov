// camera_spherical.pov -- spherical camera (360 x 180).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { spherical location <0, 1.5, -2.5> look_at <0, 1.2, 5> angle 360 180 }
#include "camera_scene.inc"
