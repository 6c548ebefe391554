// superellipsoid: a rounded box, a sphere, a cushion, an octahedron and pinched
// stars (exponents above 2), transformed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -11> look_at <0, 0, 0> angle 45 }
light_source { <-10, 20, -15> rgb 1 }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.4 } }
superellipsoid { <0.1, 0.1> pigment { rgb <1, 0.3, 0.2> } rotate y*30 translate <-3, 0, 1.5> }
superellipsoid { <1, 1> pigment { rgb <0.2, 0.8, 0.3> } translate <0, 0, 1.5> }
superellipsoid { <0.3, 1.5> pigment { rgb <0.3, 0.4, 1> } rotate <30, 20, 0> translate <3, 0, 1.5> }
superellipsoid { <2, 2> pigment { rgb <1, 0.9, 0.3> } finish { phong 0.6 } rotate y*20 translate <-3, 0, -1.5> }
superellipsoid { <3, 3> pigment { rgb <0.9, 0.5, 1> } scale 1.3 rotate <-15, 30, 0> translate <0, 0, -1.5> }
superellipsoid { <0.5, 2.5> pigment { rgb <0.3, 0.9, 1> } scale <1.2, 1, 1> rotate x*-60 translate <3, 0, -1.5> }
