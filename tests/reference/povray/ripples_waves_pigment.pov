// ripples and waves as pigments (number_of_waves 10, the default), with
// frequency and phase, which both patterns take twice: for the spacing of
// their waves and again when the colour map reads them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 10, 0> look_at 0 right x*16 up z*12 sky z }
#declare Map = color_map { [0 rgb <0, 0.1, 0.3>] [1 rgb <1, 0.9, 0.6>] }
plane { y, 0 finish { ambient 1 diffuse 0 }
  pigment { gradient x
    pigment_map {
      [0.25 waves color_map { Map }]
      [0.25 ripples frequency 2 phase 0.3 color_map { Map } scale 1.5]
      [0.5 ripples frequency 2 phase 0.3 color_map { Map } scale 1.5]
      [0.5 waves frequency 0.7 phase 0.2 color_map { Map } rotate 30*x]
      [0.75 waves frequency 0.7 phase 0.2 color_map { Map } rotate 30*x]
      [0.75 ripples color_map { Map }]
    }
    scale 16 translate -8*x }
}
