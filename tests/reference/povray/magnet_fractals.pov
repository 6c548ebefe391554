// The magnet fractals against POV-Ray 3.7 (escape past a squared modulus of
// 10000, or within 0.01 of the fixed point 1): magnet 1 and 2, mandel and
// julia, with the default exterior and interior types.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right x * 8 up y * 6 }
light_source { <0, 0, -10> rgb 1 }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.3>] [0.3 rgb <0.9, 0.4, 0.1>] [0.6 rgb <1, 0.9, 0.5>] [1 rgb 1] }
plane { -z, 0 pigment { magnet 1 mandel 40 color_map { Map } translate <-2.2, 1.6, 0> } finish { ambient 1 diffuse 0 }
  clipped_by { box { <-4, 0, -1>, <0, 3, 1> } } }
plane { -z, 0 pigment { magnet 2 mandel 40 color_map { Map } translate <2, 1.6, 0> } finish { ambient 1 diffuse 0 }
  clipped_by { box { <0, 0, -1>, <4, 3, 1> } } }
plane { -z, 0 pigment { magnet 1 julia <0.353, 0.288>, 40 color_map { Map } translate <-2, -1.5, 0> } finish { ambient 1 diffuse 0 }
  clipped_by { box { <-4, -3, -1>, <0, 0, 1> } } }
plane { -z, 0 pigment { magnet 2 julia <0.6, 0.4>, 40 color_map { Map } translate <2, -1.5, 0> } finish { ambient 1 diffuse 0 }
  clipped_by { box { <0, -3, -1>, <4, 0, 1> } } }
