// camera_focal_blur.pov -- depth of field: perspective camera with aperture,
// blur_samples and focal_point (focused on the middle sphere). POV-Ray
// places its blur samples with its own random numbers, so pixel equality is
// not expected; SSIM measures how alike the blur looks.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 0.8, 0> angle 45
  aperture 0.6 blur_samples 24 focal_point <0, 0.8, 0> confidence 0.95 variance 1/256 }
background { color rgb <0.6, 0.7, 0.9> }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.3 scale 0.5 } }
sphere { <-1.3, 0.8, -3>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.3, 0.8, 0.3> } }
sphere { <2.5, 0.8, 5>, 0.8 pigment { color rgb <0.3, 0.4, 0.9> } }
