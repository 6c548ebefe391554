// The square and triangular block patterns against POV-Ray 3.7: default
// colours, given colours and pigments, transformed, and as texture lists.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 9, -6> look_at <0, 0, 0.5> angle 60 }
light_source { <-4, 10, -6> rgb 1 }
plane { y, 0 pigment { square } finish { ambient 0.3 diffuse 0.7 } clipped_by { box { <-6, -1, 0>, <0, 1, 6> } } }
plane { y, 0 pigment { triangular } finish { ambient 0.3 diffuse 0.7 } clipped_by { box { <0, -1, 0>, <6, 1, 6> } } }
plane { y, 0
  pigment { square pigment { rgb <0.9, 0.8, 0.2> }, pigment { checker rgb 0.2, rgb 0.8 scale 0.25 }, pigment { rgb <0.1, 0.3, 0.7> }, pigment { rgb 1 } scale 0.7 rotate 20 * y }
  clipped_by { box { <-6, -1, -6>, <0, 1, 0> } }
}
plane { y, 0
  texture { triangular
    texture { pigment { rgb <1, 0.5, 0> } }, texture { pigment { rgb <0.2, 0.6, 0.2> } },
    texture { pigment { rgb <0.3, 0.3, 0.9> } }, texture { pigment { rgb 0.9 } },
    texture { pigment { rgb 0.2 } }, texture { pigment { rgb <0.8, 0.1, 0.5> } }
    scale 1.3 translate <0.3, 0, 0.2> }
  clipped_by { box { <0, -1, -6>, <6, 1, 0> } }
}
