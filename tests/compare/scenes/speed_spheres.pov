// speed_spheres.pov -- a timing scene: 900 reflective spheres on a 30 x 30
// grid over a checker floor, two point lights, reflections up to depth 5.
// Uses only what every rts has (sphere, plane, checker, finish, point lights)
// so the speed ratio is measured on a render that takes POV-Ray a while.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0, 6, -16> look_at <0, 0, 2> angle 55 }
background { color rgb <0.55, 0.65, 0.85> }
light_source { <-10, 15, -12> color rgb 0.9 }
light_source { <12, 10, -6> color rgb 0.4 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.25 } finish { reflection 0.2 } }
#declare I = 0;
#while (I < 30)
  #declare J = 0;
  #while (J < 30)
    sphere { <(I - 14.5) * 0.7, 0.3, (J - 14.5) * 0.7>, 0.3
      pigment { color rgb <0.3 + 0.7 * I / 29, 0.4, 1 - 0.7 * J / 29> }
      finish { phong 0.6 phong_size 40 reflection 0.35 } }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
