// includes.pov -- names from the standard include files: colors.inc,
// textures.inc, metals.inc, glass.inc, woods.inc, stones.inc (the stone and
// wood textures use POV-Ray's noise: small differences are expected there).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
#include "colors.inc"
#include "textures.inc"
#include "metals.inc"
#include "glass.inc"
#include "woods.inc"
#include "stones.inc"
camera { location <0, 3, -9> look_at <0, 0.8, 0> angle 50 }
background { color SkyBlue }
light_source { <-6, 10, -8> color White }
light_source { <6, 6, -6> color Gray30 }

plane { y, 0 texture { pigment { checker color White color DarkSlateGray } } }
sphere { <-3.2, 1, 0>, 0.9 texture { T_Gold_3C } }
sphere { <-1.1, 1, 0>, 0.9 texture { T_Chrome_4D } }
sphere { <1.0, 1, 0>, 0.9 texture { T_Glass3 } interior { I_Glass } }
sphere { <3.1, 1, 0>, 0.9 texture { T_Stone8 scale 0.5 } }
box { <-1, 0, -0.5>, <1, 0.8, 0.5> texture { T_Wood10 scale 0.3 rotate y*90 } translate <-1.8, 0, -2.4> }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> texture { Jade } rotate y*20 translate <1.8, 0, -2.4> }
sphere { <0, 0.4, -3.2>, 0.4 texture { pigment { color NeonPink } finish { Shiny } } }
