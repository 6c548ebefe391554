// blob: a component with a see-through texture tints the shadow by its share of the field.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 5, -6> look_at <0, 0, 0> angle 50 }
light_source { <2, 10, -3> rgb 1 }
plane { y, -1 pigment { rgb 0.9 } }
blob { threshold 0.5
  sphere { <-0.8, 0.3, 0>, 1.2, 1 pigment { rgbf <1, 0.2, 0.2, 0.8> } }
  sphere { <0.8, 0.3, 0>, 1.2, 1 }
  pigment { rgb <0.2, 0.4, 1> }
}
