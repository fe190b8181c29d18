// min_extent / max_extent of text objects: POV-Ray's union box, joined once from the
// glyphs' header boxes after layout, then moved as a box by the 0.001-degree turn and by
// every later transform (each one a looser box). Used by shapes.inc's text macros.
#version 3.7;
#macro P(Name, T)
  #local A = min_extent(T);
  #local B = max_extent(T);
  #debug concat(Name, " min ", vstr(3, A, " ", 0, 9), "\n")
  #debug concat(Name, " max ", vstr(3, B, " ", 0, 9), "\n")
#end
#debug "BEGIN\n"
P("pov", text { ttf "timrom.ttf" "POV" 1, 0 })
P("internal", text { internal 1 "POV" 1, 0 })
P("offset", text { ttf "timrom.ttf" "POV" 1, <0.1, 0.2, 0.3> })
P("space", text { ttf "timrom.ttf" "A " 1, 0 })
P("empty", text { ttf "timrom.ttf" "" 1, 0 })
P("kern", text { ttf "timrom.ttf" "AV" 1, 0 })
P("rotated", text { ttf "timrom.ttf" "P" 2, 0 rotate 45*y })
P("twice", text { ttf "timrom.ttf" "I" 1, 0 rotate 30*z rotate 30*x })
P("cyrvetic", text { ttf "cyrvetic" "Hello, World" 0.25, 0.02 scale <2, 3, 4> translate -x })
P("crystal", text { ttf "crystal.ttf" "gy" 0.1, 0 matrix <1, 0.5, 0, 0, 1, 0, 0, 0, 1, 1, 2, 3> })
#declare T = text { ttf "timrom.ttf" "Wq" -0.5, 0 }
P("negative", T)
P("copy", object { T scale 2 rotate <10, 20, 30> })
#declare Small = text { internal 3 "x" 1e-3, 0 scale 1e-3 }
P("small", Small)
#debug "END\n"
