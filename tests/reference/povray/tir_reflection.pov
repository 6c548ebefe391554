// Total internal reflection takes the place of a surface's own reflection, as
// in POV-Ray 3.7: seen from under water (ior 1.3) past the critical angle, a
// surface with reflection 0.3 shows the floor at full strength, its ambient
// light still added; nearer the vertical it reflects 0.3 and lets light out.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, 0> look_at <0, 3, 0.4> sky z angle 150 }
light_source { <0, 100, 0> rgb 0.5 }
background { rgb <0.3, 0.5, 0.9> }
plane { y, 0 pigment { checker rgb <0.8, 0.3, 0.2>, rgb <0.2, 0.5, 0.3> } finish { ambient 0.6 diffuse 0.4 } }
plane { y, 10 hollow on pigment { rgbf <0.9, 1, 1, 0.5> } finish { reflection 0.3 ambient 0.2 diffuse 0 } interior { ior 1.3 } }
