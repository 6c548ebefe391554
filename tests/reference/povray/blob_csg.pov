// blob in CSG: a difference with a box, an intersection with an inverse sphere,
// and a blob of cylinders cut by clipped_by.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <3, 4, -6> look_at <0, 0, 0> angle 45 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, -1.5 pigment { rgb 0.7 } }
difference {
  blob { threshold 0.5
    sphere { <-0.8, 0, 0>, 1.3, 1 }
    sphere { <0.8, 0, 0>, 1.3, 1 }
    cylinder { <0, -1, 0>, <0, 1, 0>, 0.7, 1 }
    pigment { rgb <1, 0.6, 0.2> }
  }
  box { <-3, 0.2, -3>, <0, 3, 0> pigment { rgb <0.2, 0.4, 1> } }
}
intersection {
  blob { threshold 0.4 sphere { 0, 1, 1 } sphere { <0.6, 0.5, 0>, 0.8, 1 } }
  sphere { <0.3, 0.2, -0.3>, 0.7 inverse }
  pigment { rgb <0.3, 1, 0.4> }
  translate <1.5, 0, -1.5>
}
blob { threshold 0.3
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.5, 1 }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.5, 1 }
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.5, 1 }
  clipped_by { plane { z, 0.2 } }
  pigment { rgb <1, 0.3, 0.8> }
  translate <-2, 0.3, -1>
}
