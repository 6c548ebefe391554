// quadric: paraboloid, hyperboloid and a tilted ellipsoid cut by a plane and a box.
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> }
light_source { <4, 8, -6> rgb 1 }
plane { y, -1 pigment { checker rgb 1, rgb 0.3 } }
intersection { quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 } plane { y, 1.5 } translate <-1.8, -0.5, 0> pigment { rgb <1, 0.3, 0.2> } }
intersection { quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.2 } box { -1, 1 } pigment { rgb <0.2, 0.8, 0.3> } }
intersection { quadric { <1, 2, 1>, <0.5, 0, 0>, <0, 0, 0.2>, -0.6 } pigment { rgb <0.3, 0.4, 1> } translate <1.9, 0, 0> }
