// camera_panoramic.pov -- panoramic (cylindrical) camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { panoramic location <0, 1.5, -2.5> look_at <0, 1.2, 5> angle 200 }
#include "camera_scene.inc"
