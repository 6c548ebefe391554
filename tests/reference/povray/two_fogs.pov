// fog.rts -- ground fog in a valley of columns, under a sky sphere
//
// What it shows
//   A ground fog (fog_type 2): full density below fog_offset 0.4, thinning as
//   1 / (1 + ((h - 0.4) / fog_alt)^2) above it, so the columns' feet vanish in
//   the fog while their tops stay clear; a thin constant fog (fog_type 1) adds
//   haze with distance. Rays that hit nothing see the sky_sphere's pigment
//   (evaluated by direction) under the fog. As in POV-Ray, the two fogs'
//   colours add up where both are thick, so each is given a dim colour.
//
// Render
//   cargo run --release -- render examples/fog.rts -o fog.png -W 640 -H 480
//   povray +Iexamples/fog.rts +Ofog.png +W640 +H480 -D -A

#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -8> look_at <0, 1, 0> angle 60 }

sky_sphere { pigment { rgb <0.35, 0.5, 0.85> } }

plane { y, 0 pigment { checker rgb <0.3, 0.5, 0.2>, rgb <0.2, 0.35, 0.15> scale 2 } }

#declare I = 0;
#while (I < 6)
  box { <-0.3, 0, -0.3>, <0.3, 3, 0.3> translate <-3, 0, I * 4> pigment { rgb <0.9, 0.85, 0.7> } }
  box { <-0.3, 0, -0.3>, <0.3, 3, 0.3> translate < 3, 0, I * 4> pigment { rgb <0.9, 0.85, 0.7> } }
  #declare I = I + 1;
#end

light_source { <10, 20, -10>, rgb 1 }

fog { fog_type 2 distance 1.5 color rgb <0.6, 0.6, 0.65> fog_offset 0.4 fog_alt 0.3 }
fog { distance 60 color rgb <0.25, 0.27, 0.3> }
