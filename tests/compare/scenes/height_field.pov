// height_field.pov -- height_field from a PNG (smooth and faceted), and an
// image_map on a box; both read files from ../assets.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 50 }
background { color rgb <0.6, 0.7, 0.85> }
light_source { <-5, 10, -6> color rgb 1 }
light_source { <6, 6, -6> color rgb 0.3 }

plane { y, 0 pigment { color rgb <0.35, 0.35, 0.4> } }
height_field { png "../assets/hf.png" smooth
  pigment { gradient y color_map { [0 color rgb <0.2, 0.5, 0.2>] [1 color rgb <0.95, 0.95, 0.9>] } }
  translate <-0.5, 0, -0.5> scale <4, 1.5, 4> translate <-1.6, 0, 0.5>
}
height_field { png "../assets/hf.png"
  pigment { color rgb <0.85, 0.6, 0.35> }
  translate <-0.5, 0, -0.5> scale <2, 0.8, 2> rotate y*90 translate <2.2, 0, -0.5>
}
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6>
  pigment { image_map { png "../assets/tiles.png" } translate <-0.5, -0.5, 0> scale 1.2 }
  rotate y*-20 translate <1.2, 0, -2.2>
}
