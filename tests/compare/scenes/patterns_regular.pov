// patterns_regular.pov -- checker, hexagon, brick, gradient (color_map),
// radial, onion on six tiles.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 50 }
background { color rgb 0.1 }
light_source { <0, 0, -20> color rgb 1 }

#declare Tile = box { <-1.4, -1.4, 0>, <1.4, 1.4, 0.2> }
#declare F = finish { ambient 0.2 diffuse 0.8 }
object { Tile pigment { checker color rgb <0.9, 0.2, 0.2> color rgb <0.95, 0.95, 0.9> scale 0.5 }
  finish { F } translate <-3, 1.5, 0> }
object { Tile pigment { hexagon color rgb <0.2, 0.3, 0.9> color rgb <0.95, 0.9, 0.3> color rgb <0.2, 0.8, 0.3>
  scale 0.35 rotate x*-90 } finish { F } translate <0, 1.5, 0> }
object { Tile pigment { brick color rgb 0.8 color rgb <0.7, 0.25, 0.15> brick_size <0.6, 0.25, 0.3> mortar 0.05 }
  finish { F } translate <3, 1.5, 0> }
object { Tile pigment { gradient x color_map { [0 color rgb <0.1, 0.1, 0.6>] [0.5 color rgb <0.9, 0.9, 0.2>] [1 color rgb <0.8, 0.1, 0.1>] }
  scale 2.8 translate -1.4*x } finish { F } translate <-3, -1.5, 0> }
object { Tile pigment { radial frequency 8 color_map { [0 color rgb <0.9, 0.4, 0.1>] [0.5 color rgb <0.9, 0.4, 0.1>] [0.5 color rgb 0.95] [1 color rgb 0.95] }
  rotate x*-90 } finish { F } translate <0, -1.5, 0> }
object { Tile pigment { onion color_map { [0 color rgb <0.2, 0.6, 0.9>] [0.5 color rgb <0.9, 0.9, 0.95>] [1 color rgb <0.2, 0.6, 0.9>] }
  scale 0.5 } finish { F } translate <3, -1.5, 0> }
