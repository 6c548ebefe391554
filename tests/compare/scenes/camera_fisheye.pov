// camera_fisheye.pov -- fisheye camera, 180 degrees.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { fisheye location <0, 1.2, -1.5> look_at <0, 1.2, 5> angle 180 }
#include "camera_scene.inc"
