// meshes.pov -- mesh (triangle + smooth_triangle), mesh2, polygon.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
background { color rgb <0.6, 0.7, 0.85> }
light_source { <-5, 9, -8> color rgb 1 }
light_source { <6, 6, -6> color rgb 0.3 }

plane { y, 0 pigment { color rgb <0.75, 0.72, 0.65> } }
// a faceted and a smooth pyramid-ish dome from triangles
mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.6, 0> }
  triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.6, 0> }
  triangle { <1, 0, 1>, <-1, 0, 1>, <0, 1.6, 0> }
  triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.6, 0> }
  pigment { color rgb <0.9, 0.35, 0.25> } finish { phong 0.5 }
  translate <-2.4, 0, 0.5>
}
mesh {
  smooth_triangle { <-1, 0, -1>, <-0.5, 0.5, -0.7>, <1, 0, -1>, <0.5, 0.5, -0.7>, <0, 1.6, 0>, <0, 1, 0> }
  smooth_triangle { <1, 0, -1>, <0.5, 0.5, -0.7>, <1, 0, 1>, <0.7, 0.5, 0.5>, <0, 1.6, 0>, <0, 1, 0> }
  smooth_triangle { <1, 0, 1>, <0.7, 0.5, 0.5>, <-1, 0, 1>, <-0.5, 0.5, 0.7>, <0, 1.6, 0>, <0, 1, 0> }
  smooth_triangle { <-1, 0, 1>, <-0.5, 0.5, 0.7>, <-1, 0, -1>, <-0.5, 0.5, -0.7>, <0, 1.6, 0>, <0, 1, 0> }
  pigment { color rgb <0.3, 0.6, 0.95> } finish { phong 0.7 phong_size 30 }
  translate <0, 0, 0.5>
}
// a mesh2 octahedron
mesh2 {
  vertex_vectors { 6, <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
  face_indices { 8,
    <0, 2, 4>, <2, 1, 4>, <1, 3, 4>, <3, 0, 4>,
    <0, 5, 2>, <2, 5, 1>, <1, 5, 3>, <3, 5, 0> }
  pigment { color rgb <0.35, 0.85, 0.4> } finish { specular 0.5 }
  rotate y*30 translate <2.4, 1, 0.5>
}
// a star polygon standing up
polygon { 11,
  <0, 1>, <0.22, 0.31>, <0.95, 0.31>, <0.36, -0.12>, <0.59, -0.81>,
  <0, -0.38>, <-0.59, -0.81>, <-0.36, -0.12>, <-0.95, 0.31>, <-0.22, 0.31>, <0, 1>
  pigment { color rgb <0.95, 0.8, 0.2> }
  scale 0.7 translate <-0.9, 0.9, -2>
}
