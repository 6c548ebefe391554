// photons.pov -- POV-Ray 3.7 photons: a glass ball focusing light into its
// shadow, a polished ring reflecting a cardioid onto the floor, a coloured
// glass column refracting a line of light; a second light that shoots no
// photons (its filtered shadows stay); collect off on the glass and metal.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  photons { spacing 0.004 }
}
camera { location <0, 5.5, -6.5> look_at <0, 0.2, 0.4> angle 44 }
light_source { <-7, 6, 3> color rgb 1.1 }
light_source { <3, 8, -6> color rgb 0.25 photons { reflection off refraction off } }
plane { y, 0 pigment { rgb <0.86, 0.84, 0.8> } finish { ambient 0.02 diffuse 0.8 } }
sphere { <-1.6, 0.8, -0.6>, 0.8
  pigment { rgbf <0.98, 0.99, 1, 0.97> }
  finish { ambient 0 diffuse 0 specular 0.7 roughness 0.003 }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}
difference {
  cylinder { <0, 0, 0>, <0, 0.7, 0>, 1.1 }
  cylinder { <0, -0.1, 0>, <0, 0.8, 0>, 1.03 }
  translate <1.3, 0, 1.0>
  pigment { rgb <0.95, 0.6, 0.4> }
  finish { ambient 0 diffuse 0.15 specular 0.6 roughness 0.01 reflection { 0.85 metallic } }
  photons { target reflection on collect off }
}
cylinder { <0, 0, 0>, <0, 1.5, 0>, 0.32
  translate <0.6, 0, -1.6>
  pigment { rgbf <1, 0.35, 0.3, 0.92> }
  finish { ambient 0 diffuse 0 specular 0.5 roughness 0.005 }
  interior { ior 1.45 }
  photons { target refraction on reflection off collect off }
}
