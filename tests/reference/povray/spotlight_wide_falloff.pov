// A spotlight with half-angles past 90 degrees (radius 50, falloff 100), as POV-Ray's
// lights/laser.pov has: lit in front, nothing behind the light's plane.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 20, -0.01> look_at 0 angle 120 }
light_source { <0, 1, 0> color rgb 1 spotlight point_at <0, 0, 1> radius 50 falloff 100 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
