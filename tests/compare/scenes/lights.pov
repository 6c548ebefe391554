// lights.pov -- spotlight (radius, falloff, tightness), cylinder light,
// area light (5x5, no jitter: deterministic in POV-Ray), light fading
// (fade_distance, fade_power), shadowless light, looks_like.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 0.5, 0> angle 50 }
background { color rgb 0.05 }

light_source { <-3, 6, -2> color rgb <1, 0.9, 0.7> spotlight point_at <-3, 0, 0> radius 12 falloff 20 tightness 10 }
light_source { <3, 6, 0> color rgb <0.6, 0.8, 1> cylinder point_at <3, 0, 0> radius 1.2 falloff 1.8 }
light_source { <0, 4, -3> color rgb 0.6 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 adaptive 0 fade_distance 3 fade_power 2 }
light_source { <0, 10, -10> color rgb 0.1 shadowless }
light_source { <-1.6, 0.35, -2> color rgb <1, 0.5, 0.2> fade_distance 1 fade_power 1
  looks_like { sphere { 0, 0.15 pigment { color rgb <1, 0.7, 0.4> } finish { ambient 1 diffuse 0 } } } }

plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.02 } }
sphere { <-3, 1, 0>, 0.8 pigment { color rgb <0.9, 0.4, 0.3> } }
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> translate <3, 0, 0> pigment { color rgb <0.4, 0.8, 0.4> } }
sphere { <0, 0.7, 0>, 0.7 pigment { color rgb <0.4, 0.5, 0.9> } }
