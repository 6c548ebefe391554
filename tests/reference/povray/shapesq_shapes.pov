// shapesq.inc's quartics as rts writes them from the manual's equations (and
// POV-Ray's own shapesq.inc when POV-Ray renders this): Bicorn, Piriform,
// Steiner_Surface and the clipped Helix (after shapes.inc, as POV-Ray's
// sample scenes include them).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"
camera { location <0, 3, -12> look_at <0, 0, 0> angle 45 }
light_source { <10, 20, -30> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
#declare T = texture { pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 } }
object { Bicorn texture { T } clipped_by { box { -1.5, 1.5 } } scale 1.2 translate <-3, 1.5, 0> }
object { Piriform sturm texture { T } rotate -90*z scale <1.5, 3, 1.5> translate <3, 2, 0> }
object { Steiner_Surface texture { T } clipped_by { sphere { 0, 1 } } scale 4 rotate <50, -25, 0> translate <-2.5, -2, 0> }
object { Helix texture { T } rotate -90*x translate <3, -3, 0> }
