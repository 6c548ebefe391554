// spiral2 against POV-Ray 3.7: its value (spiral1's and the radius's rings,
// each a triangle wave, added) under a colour map, with the default triangle
// wave and with ramp_wave and frequency.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 60 }
light_source { <0, 0, -10> rgb 1 }
plane { z, 0
  pigment { spiral2 5 color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb 1] } scale 0.8 }
  finish { ambient 1 diffuse 0 }
  clipped_by { box { <-5, -5, -1>, <0, 5, 1> } }
}
plane { z, 0
  pigment { spiral2 3 ramp_wave frequency 0.5 color_map { [0 rgb <0.6, 0.1, 0.1>] [1 rgb <0.9, 0.9, 0.6>] } scale 1.3 translate <1, 0.5, 0> }
  finish { ambient 1 diffuse 0 }
  clipped_by { box { <0, -5, -1>, <5, 5, 1> } }
}
