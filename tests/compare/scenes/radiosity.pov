// radiosity.pov -- POV-Ray 3.7 radiosity: a room lit by one light through
// colour bleeding from red and green walls, two bounces, an emissive panel,
// an object invisible to radiosity (no_radiosity) and one of low importance.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  radiosity { count 100 error_bound 0.8 recursion_limit 2 nearest_count 6
              pretrace_start 0.08 pretrace_end 0.01 }
}
camera { location <0, 2.2, -5.5> look_at <0, 1.3, 0> angle 60 }
light_source { <1.2, 3.6, -1.5> color rgb 1.2 }
#default { finish { ambient 0 diffuse 0.75 } }

box { <-3, 0, -6>, <3, 4, 3> pigment { rgb 0.85 } hollow }
box { <-3.01, 0, -6>, <-2.9, 4, 3> pigment { rgb <0.8, 0.15, 0.12> } }
box { <2.9, 0, -6>, <3.01, 4, 3> pigment { rgb <0.15, 0.7, 0.2> } }
box { <-0.8, 0, -0.6>, <0.6, 1.8, 0.8> rotate y*25 translate <-1, 0, 0.8> pigment { rgb 0.8 } }
sphere { <1.2, 0.7, 0.2>, 0.7 pigment { rgb <0.9, 0.8, 0.3> } radiosity { importance 0.5 } }
box { <-1, 3.9, 1.5>, <1, 3.99, 2.5> pigment { rgb <1, 0.9, 0.7> } finish { emission 2 diffuse 0 } }
sphere { <-2.2, 0.3, -1.5>, 0.3 pigment { rgb 0.05 } no_radiosity }
