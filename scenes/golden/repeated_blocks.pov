// Repeated blocks modify, they do not restart (notes/parser-rules.md §2): a second finish,
// pigment, normal or interior block continues from the first; a loose pigment or finish
// edits the top texture layer; `finish { F phong 1 }` starts from F; #defaults accumulate.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -10> look_at <0, 0.2, 0> angle 48 }
light_source { <-6, 8, -9> color rgb 1 }
light_source { <7, 3, -5> color rgb 0.35 }
background { color rgb <0.1, 0.12, 0.15> }
plane { y, -2.2 pigment { checker rgb 0.8 rgb 0.25 } }

// LDraw exporters: two finishes in one texture; the second keeps ambient 0.3 diffuse 0.4.
sphere { <-3.3, 1.4, 0>, 1
  texture {
    pigment { rgb <0.8, 0.15, 0.1> }
    finish { ambient 0.3 diffuse 0.4 }
    finish { phong 0.8 reflection 0.2 }
  }
}

// A second pigment with a new pattern keeps the colour map and the scale.
sphere { <0, 1.4, 0>, 1
  pigment { gradient x color_map { [0 rgb <1, 0.9, 0>] [1 rgb <0, 0.2, 1>] } scale 0.5 }
  pigment { gradient y }
  normal { bumps 1.5 scale 0.15 }
  normal { scale 2 }
}

// A second pigment with only a transform stays the colour it was; a finish identifier
// first, then an override.
#declare Shiny = finish { ambient 0.05 diffuse 0.9 phong 0.2 phong_size 20 };
sphere { <3.3, 1.4, 0>, 1
  pigment { rgb <0.1, 0.7, 0.2> }
  pigment { translate x }
  finish { Shiny phong 1 }
}

// Two interiors: the second adds fade to the first's ior.
sphere { <-3.3, -1, 0>, 1
  pigment { rgbf <0.9, 0.95, 1, 0.9> }
  finish { ambient 0 diffuse 0.1 phong 0.6 }
  interior { ior 1.5 }
  interior { fade_distance 1.5 fade_power 2 }
}

// Layers: a loose pigment edits the top layer's pigment (its pattern and map stay, it
// is scaled) and a loose finish edits that layer's finish (its phong stays).
sphere { <0, -1, 0>, 1
  texture { pigment { rgb <1, 0.85, 0.1> } }
  texture {
    pigment { gradient x color_map { [0.5 rgbt <0.1, 0.3, 1, 0>] [0.5 rgbt 1] } }
    finish { phong 1 phong_size 8 }
  }
  pigment { scale 0.4 }
  finish { ambient 0.25 }
}

// #default twice: both finishes stay in effect.
#default { finish { ambient 0.45 } }
#default { finish { diffuse 0.25 } }
sphere { <3.3, -1, 0>, 1 pigment { rgb <0.9, 0.4, 0.8> } }
