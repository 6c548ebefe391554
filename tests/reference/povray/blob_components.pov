// blob: spherical and cylindrical components, a negative one, the old `component`,
// component transforms (an ellipsoid) and textures blended by field weight.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2, 4, -7> look_at <0, 0.3, 0> angle 45 }
light_source { <-10, 20, -15> rgb 1 }
light_source { <10, 5, -5> rgb 0.4 }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.4 } }
blob {
  threshold 0.6
  sphere { <-1, 0, 0>, 1.2, 1 pigment { rgb <1, 0.2, 0.1> } }
  sphere { <1, 0, 0>, 1.2, strength 1 scale <1, 1.5, 1> rotate z*20 }
  cylinder { <-1, 1, 0>, <1.5, 1.5, 0.5>, 0.6, 1.5 texture { pigment { rgb <0.1, 0.3, 1> } finish { phong 0.8 } } }
  sphere { <0, 0.3, -0.6>, 0.8, -1.5 }
  component 1, 0.9, <0, -0.6, 1>
  pigment { rgb <0.2, 0.9, 0.3> }
  finish { specular 0.5 }
  rotate y*20
}
