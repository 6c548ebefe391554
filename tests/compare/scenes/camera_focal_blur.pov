// camera_focal_blur.pov -- depth of field: perspective camera with aperture,
// blur_samples and focal_point (focused on the middle sphere). POV-Ray
// places its blur samples with its own random numbers, so the noise of two
// renders can never agree: the samples and variance here are enough for both
// pictures to settle, so SSIM measures the lens (aperture, focal point, blur)
// and not the noise. At blur_samples 24 and variance 1/256 POV-Ray's own
// picture scored SSIM 0.943 against its converged one (640x480), so no other
// sampler could reach 0.95 there; rts scored 0.908 against it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 0.8, 0> angle 45
  aperture 0.6 blur_samples 150 focal_point <0, 0.8, 0> confidence 0.95 variance 1/10000 }
background { color rgb <0.6, 0.7, 0.9> }
light_source { <-6, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.3 scale 0.5 } }
sphere { <-1.3, 0.8, -3>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.3, 0.8, 0.3> } }
sphere { <2.5, 0.8, 5>, 0.8 pigment { color rgb <0.3, 0.4, 0.9> } }
