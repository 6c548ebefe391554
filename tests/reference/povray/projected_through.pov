// projected_through: a point light shines only through a box with a hole (a
// spot shaped like the hole on the floor; the mask itself is not drawn and
// casts no shadow), an area light only through a sphere (a spot with soft
// edges), and a ball between the first light and its mask casts no shadow.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -6> look_at <0, 0, 0> angle 60 }
light_source { <0, 10, -5> rgb 0.15 shadowless }
#declare Frame = difference { box { <-1, -0.05, -1>, <1, 0.05, 1> } box { <-0.5, -1, -0.3>, <0.5, 1, 0.6> } }
light_source { <-2, 6, 0> rgb 1 projected_through { object { Frame translate <-2, 3, 0> } } }
light_source { <2, 6, 0> rgb 1 area_light x, z, 5, 5 adaptive 1
  projected_through { sphere { <2, 3, 0>, 0.6 } } }
sphere { <-2, 4.5, 0>, 0.4 pigment { rgb <1, 0.4, 0.2> } }
sphere { <2.2, 0.5, 0.2>, 0.5 pigment { rgb <0.3, 0.5, 1> } }
plane { y, 0 pigment { rgb 0.8 } }
