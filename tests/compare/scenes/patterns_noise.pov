// patterns_noise.pov -- bozo, spotted, marble (turbulence), wood, granite,
// agate, leopard, and bozo with turbulence/octaves/omega/lambda.
// POV-Ray's noise is its own; pixel equality is not expected: the SSIM here
// measures how close rts's noise looks, and may stay under 0.95.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 54 }
background { color rgb 0.1 }
light_source { <0, 0, -20> color rgb 1 }

#declare Tile = box { <-1.1, -1.1, 0>, <1.1, 1.1, 0.2> }
#declare F = finish { ambient 0.2 diffuse 0.8 }
#declare CM = color_map { [0 color rgb <0.1, 0.2, 0.7>] [1 color rgb <0.95, 0.95, 1>] }
object { Tile pigment { bozo color_map { CM } scale 0.4 } finish { F } translate <-3.6, 1.2, 0> }
object { Tile pigment { spotted color_map { [0 color rgb <0.95, 0.9, 0.6>] [1 color rgb <0.3, 0.5, 0.2>] } scale 0.3 }
  finish { F } translate <-1.2, 1.2, 0> }
object { Tile pigment { marble turbulence 0.8 color_map { [0 color rgb 0.9] [0.8 color rgb <0.5, 0.2, 0.2>] [1 color rgb 0.2] } scale 0.8 }
  finish { F } translate <1.2, 1.2, 0> }
object { Tile pigment { wood turbulence 0.05 color_map { [0 color rgb <0.85, 0.6, 0.3>] [1 color rgb <0.45, 0.25, 0.1>] } scale 0.15 rotate x*80 }
  finish { F } translate <3.6, 1.2, 0> }
object { Tile pigment { granite color_map { [0 color rgb 0.9] [0.5 color rgb 0.5] [1 color rgb 0.1] } scale 1.5 }
  finish { F } translate <-3.6, -1.2, 0> }
object { Tile pigment { agate agate_turb 0.5 color_map { [0 color rgb <0.9, 0.8, 0.6>] [1 color rgb <0.5, 0.3, 0.2>] } scale 0.6 }
  finish { F } translate <-1.2, -1.2, 0> }
object { Tile pigment { leopard color_map { [0 color rgb <0.95, 0.8, 0.4>] [1 color rgb <0.2, 0.1, 0.05>] } scale 0.12 }
  finish { F } translate <1.2, -1.2, 0> }
object { Tile pigment { bozo turbulence 0.6 octaves 4 omega 0.6 lambda 2.5 color_map { CM } scale 0.5 }
  finish { F } translate <3.6, -1.2, 0> }
