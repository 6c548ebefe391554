// A pigment, finish or normal written in a texture or an object modifies the one
// in force (POV-Ray 3.7): `pigment { }` keeps the colour, `finish { diffuse 0.5 }`
// keeps ambient 0.5, `pigment { scale 3 }` scales the declared pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> look_at <0, 0.5, 0> }
light_source { <0, 0, -10> rgb 1 }
#declare T = texture { pigment { rgb <1, 0, 0> } finish { ambient 0.5 diffuse 0 } }
#declare P = pigment { gradient x color_map { [0 rgb <0, 0, 1>] [1 rgb <1, 1, 0>] } }
sphere { <-1, 0, 0>, 0.45 texture { T } pigment { } }
sphere { <0, 0, 0>, 0.45 texture { T } finish { diffuse 0.5 } }
sphere { <1, 0, 0>, 0.45 texture { T pigment { P scale 0.5 } } }
sphere { <-1, 1, 0>, 0.45 pigment { P } pigment { scale 0.3 } translate x*0.2 }
sphere { <0, 1, 0>, 0.45 texture { T finish { } } }
sphere { <1, 1, 0>, 0.45 texture { pigment { P } finish { ambient 1 } } pigment { rotate z*90 } }
// The entries of a texture_map are texture bodies: the same rule holds there.
sphere { <0, -0.9, 0>, 0.4 texture { gradient x texture_map { [0 T finish { diffuse 0.5 }] [1 T finish { diffuse 0.5 }] } } }
