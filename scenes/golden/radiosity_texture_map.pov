// golden-args: --block-mean 8 --max-rmse 0.03 --fail 0.06 --max-bad-fraction 0
// Radiosity on blended textures: a texture_map wall, a checker of textures floor, a
// mesh2 with a uv-mapped texture_list entry and a per-vertex texture blend. Each
// stand-in texture of a blend gathers the ambient light as a plain texture does
// (radiosity was lost on them: the walls went dark).
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 0.08 pretrace_end 0.02 count 80 error_bound 0.8
              recursion_limit 2 gray_threshold 0.2 } }
#default { finish { ambient 0 diffuse 0.8 } }
camera { location <0, 1.5, -4> look_at <0, 0.9, 0> angle 55 }
light_source { <0.8, 2.3, -1.2> rgb 1 }
#declare Red = texture { pigment { rgb <0.9, 0.3, 0.2> } }
#declare Pale = texture { pigment { rgb <0.8, 0.8, 0.7> } }
box { <-2, 0, -4.5>, <2, 2.5, 2> inverse
  texture { gradient x texture_map { [0.3 Red] [0.7 Pale] } scale 4 translate -2 * x } }
plane { y, 0.001 texture { checker texture { Pale } texture { pigment { rgb 0.3 } } scale 0.5 } }
mesh2 {
  vertex_vectors { 4, <-1.5, 0.01, 1.9>, <1.5, 0.01, 1.9>, <1.5, 2, 1.9>, <-1.5, 2, 1.9> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  texture_list { 3,
    texture { uv_mapping pigment { gradient x color_map { [0 rgb <0.2, 0.9, 0.3>] [1 rgb <0.2, 0.3, 0.9>] } } }
    texture { pigment { rgb <1, 1, 0.2> } }
    texture { pigment { rgb <0.2, 1, 1> } } }
  face_indices { 2, <0, 1, 2>, 0, <0, 2, 3>, 0, 1, 2 }
}
sphere { <-0.6, 0.4, 0>, 0.4 texture { bozo texture_map { [0 Red] [1 Pale] } scale 0.2 } }
