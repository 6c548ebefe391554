// double_illuminate: a disc lit only from behind, with a second disc shadowing it.
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at 0 }
light_source { <1, 2, 6> rgb 1 }
disc { 0, -z, 2 pigment { rgb <1, 0.6, 0.3> } finish { ambient 0 diffuse 0.8 phong 1 phong_size 5 } double_illuminate }
disc { <0,0,1>, -z, 0.5 pigment { rgb 1 } finish { ambient 0 } translate <-1.5, 0, 0> }
