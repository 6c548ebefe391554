// `tiles { texture { … } tile2 texture { … } }`: POV-Ray's older checker of textures.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at 0 }
light_source { <3, 5, -5> color rgb 1 }
plane { y, 0 texture { tiles { texture { pigment { rgb <1,0,0> } } tile2 texture { pigment { rgb <0,0,1> } finish { reflection 0.3 } } } scale 0.5 rotate y*20 } }
sphere { <0,1,0>, 1 texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb 0.2 } } } scale 0.3 } }
