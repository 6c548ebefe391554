// POV-Ray's uv coordinates of box, torus, lathe and sor (the u coordinate as a
// gradient): the box's net, the torus's ring and tube, a cubic lathe's segments and
// a sor's sides with its top and bottom caps.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -8> look_at 0 angle 60 }
light_source { <0, 10, -10> rgb 1 }  // unused by the pure-ambient finish
#declare P = pigment { uv_mapping gradient x color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.9, 0.2>] } }
#declare F = finish { ambient 1 diffuse 0 }
box { <-1, -0.5, -0.7>, <1, 0.6, 0.8> pigment { P } finish { F } rotate <30, 40, 0> translate <-2.4, 1.3, 0> }
torus { 0.8, 0.35 pigment { P } finish { F } rotate <-50, 0, 20> translate <0, 1.3, 0> }
lathe { cubic_spline 6, <0.5, -1.5>, <1, -1>, <1, -0.6>, <0.5, 0.2>, <0.8, 1>, <0.3, 1.4>
  pigment { P } finish { F } rotate <25, 0, 0> translate <2.4, 1.2, 0> }
#declare S = sor { 5, <0.8, -1.2>, <0.7, -1>, <0.9, -0.2>, <0.8, 1>, <0.5, 1.5> pigment { P } finish { F } }
object { S rotate <-40, 0, 0> translate <-1.3, -1.5, 0> }
object { S rotate <-140, 0, 0> translate <1.3, -1.5, 0> }
