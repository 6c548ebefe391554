// Rainbows against POV-Ray 3.7: an arc with soft ends (falloff_angle) over
// objects (small distance), a second full ring overlapping it (several
// rainbows average), filter and transmit in the colour maps, a fog in front.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1.5, 0> angle 70 }
light_source { <-5, 8, -6> rgb 1 }
background { rgb <0.25, 0.35, 0.6> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <1.5, 1, 2>, 1 pigment { rgb <0.9, 0.6, 0.2> } finish { phong 0.5 } }
box { <-3, 0, 3>, <-1.5, 2.5, 4> pigment { rgb <0.3, 0.7, 0.4> } }
rainbow {
  angle 30 width 14 distance 20 direction <0.1, -0.25, 1>
  up <0.2, 1, 0> arc_angle 150 falloff_angle 60
  colour_map {
    [0.0 rgbf <1, 0, 1, 1>]
    [0.2 rgbft <0.5, 0, 1, 0.5, 0.2>]
    [0.5 rgbf <0, 1, 0, 0.3>]
    [0.8 rgbt <1, 0.5, 0, 0.1>]
    [1.0 rgbf <1, 0, 0, 1>]
  }
}
rainbow {
  angle 12 width 8 direction <-0.2, -0.1, 1>
  colour_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <0.2, 0.4, 1, 0.4>] [1 rgbt <1, 1, 1, 1>] }
}
fog { distance 40 rgbt <0.7, 0.7, 0.8, 0.2> }
