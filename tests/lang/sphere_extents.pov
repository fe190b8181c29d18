// min_extent / max_extent of spheres: POV-Ray moves a sphere's centre and radius for
// translate, rotate and a uniform scale, and keeps a matrix from the first other
// transform on (a scale unequal in any component, a sign included, or a matrix); its
// box is then the turned cube's box. The surface is the same.
#version 3.7;
#macro Show(Name, Obj)
  #debug concat(Name, " min ", vstr(3, min_extent(Obj), " ", 0, 6), "\n")
  #debug concat(Name, " max ", vstr(3, max_extent(Obj), " ", 0, 6), "\n")
#end
#debug "BEGIN\n"
Show("plain", sphere { <0.1, 0.2, 0.3>, 0.8 })
Show("turned", sphere { <0.1, 0.2, 0.3>, 0.8 rotate <30, 40, 50> translate x })
Show("uniform", sphere { <0.1, 0.2, 0.3>, 0.8 scale 2 rotate 45 * y scale -1 })
Show("mirrored", sphere { <0.1, 0.2, 0.3>, 0.8 scale <-1, 1, -1> })
Show("mirrored turned", sphere { <0.165, 0.077, -0.266>, 0.798 scale <-1, 1, -1> rotate <47.503, -53.559, -65.149> })
Show("turned then stretched", sphere { <0.1, 0.2, 0.3>, 0.8 rotate 45 * y scale <1, 2, 1> rotate 30 * z })
Show("moved then stretched", sphere { <1, 0, 0>, 0.5 translate <0, 1, 0> scale <2, 1, 1> translate z })
Show("identity matrix turned", sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> rotate 45 * z })
Show("transform block turned", sphere { 0, 1 transform { rotate 45 * x } rotate 45 * y })
Show("object turned", object { sphere { 0, 1 scale <1, 1, -1> } rotate 30 * x })
Show("union of turned", union { sphere { 0, 1 scale <1, 1, -1> rotate 45 * y } sphere { 3 * x, 0.5 } })
#debug "END\n"
