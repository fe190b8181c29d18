// trace(), inside(), min_extent() and max_extent() while parsing: the nearest hit and
// its normal (the leaf's, reversed on inverted leaves), POV-Ray's inside test (clips
// first), and POV-Ray's bounding boxes (a CSG's box joined when it is closed, then moved
// as a box by every transform).
// (Values get 1e-7 before printing: a zero and -1e-17 print alike.)
#version 3.7;
#macro T(Name, Obj, From, Dir)
  #local N = <9, 9, 9>;
  #local P = trace(Obj, From, Dir, N);
  #debug concat(Name, " hit ", vstr(3, P + 1e-7, " ", 0, 5), " normal ", vstr(3, N + 1e-7, " ", 0, 5), "\n")
#end
#macro I(Name, Obj, Point)
  #debug concat(Name, " inside ", str(inside(Obj, Point), 0, 0), "\n")
#end
#macro E(Name, Obj)
  #debug concat(Name, " min ", vstr(3, min_extent(Obj) + 1e-7, " ", 0, 5), "\n")
  #debug concat(Name, " max ", vstr(3, max_extent(Obj) + 1e-7, " ", 0, 5), "\n")
#end
#declare S = sphere { <1, 2, 3>, 2 }
#declare B = box { -1, 1 rotate <10, 20, 30> translate y }
#declare C = cylinder { 0, <0, 3, 0>, 0.5 scale <1, 2, 1> }
#declare K = cone { 0, 1, y * 2, 0.25 rotate 45 * z }
#declare Tor = torus { 2, 0.5 rotate 90 * x }
#declare U = union { sphere { 0, 1 } box { <2, -1, -1>, <3, 1, 1> } rotate 45 * y }
#declare Ip = intersection { sphere { 0, 2 } plane { y, 0.5 } }
#declare Iq = intersection { sphere { 0, 2 } plane { -x, 0.25 } translate z }
#declare D = difference { box { -2, 2 } sphere { 0, 2.5 } }
#declare Dn = difference { box { -1, 1 } cylinder { -2 * z, 2 * z, 0.5 } }
#declare M = merge { sphere { -x, 1 } sphere { x, 1 } scale <1, 2, 1> rotate 30 * z }
#declare Inv = sphere { 0, 1 inverse }
#declare Clip = sphere { 0, 2 clipped_by { plane { y, 0 } } }
#declare ClipInv = sphere { 0, 1 inverse clipped_by { box { -3, 3 } } }
#declare Tri = triangle { <-1, 0, -1>, <1, 0, -1>, <0, 0, 1> }
#declare Mesh = mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1, 0> }
  triangle { <1, 0, -1>, <0, 0, 1>, <0, 1, 0> }
  inside_vector y
}
#declare Pl = plane { <1, 1, 0>, 1 }
#declare Iso = isosurface { function { x * x + y * y + z * z - 1 } contained_by { box { -2, 2 } } }
#declare Txt = text { internal 1 "Hi" 0.5, 0 }
#declare Bnd = union { sphere { 0, 1 } sphere { 3 * x, 1 } bounded_by { box { -1, 1 } } }
#declare Sor = sor { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
#debug "BEGIN\n"
T("sphere", S, <1, 2, -10>, z)
T("sphere inside", S, <1, 2, 3>, <1, 1, 0>)
T("sphere miss", S, <10, 2, -10>, z)
T("box", B, <0, 1, -10>, <0, 0.1, 1>)
T("cylinder", C, <-5, 1, 0>, x)
T("cone", K, <-5, 0.5, 0>, x)
T("torus", Tor, <-10, 0, 0>, x)
T("torus hole", Tor, <0, 0, -10>, z)
T("union", U, <5, 0, 0>, -x)
T("intersection", Ip, <0, 5, 0>, -y)
T("difference", D, <0, 0, 0>, <1, 0.3, 0.2>)
T("difference hole", Dn, <0, 0, -5>, z)
T("merge", M, <0, 5, 0>, -y)
T("inverse", Inv, <0, 0, -5>, z)
T("clipped", Clip, <0, 5, 0>, -y)
T("triangle", Tri, <0.1, 5, 0>, -y)
T("triangle below", Tri, <0.1, -5, 0>, y)
T("mesh", Mesh, <0, 0.5, -5>, z)
T("plane", Pl, <0, 0, 0>, <1, 1, 0>)
T("isosurface", Iso, <0.3, 0, -5>, z)
T("text", Txt, <0.3, 0.3, -5>, z)
T("sor", Sor, <0, 0.5, -5>, z)
T("unnormalised", S, <1, 2, -10>, <0, 0, 20>)
#local NoNormal = trace(S, <1, 2, -10>, z);
#debug concat("no normal ", vstr(3, NoNormal, " ", 0, 5), "\n")
I("sphere centre", S, <1, 2, 3>)
I("sphere far", S, <5, 2, 3>)
I("box", B, <0, 1, 0>)
I("union", U, <1.5, 0, 1.5>)
I("difference", D, <0, 0, 0>)
I("difference corner", D, <1.9, 1.9, 1.9>)
I("inverse", Inv, <0, 0, 0>)
I("inverse out", Inv, <2, 0, 0>)
I("clipped above", Clip, <0, 1, 0>)
I("clipped below", Clip, <0, -1, 0>)
I("clipped inverse far", ClipInv, <5, 0, 0>)
I("clipped inverse near", ClipInv, <2, 0, 0>)
I("mesh", Mesh, <0, 0.2, -0.2>)
I("plane", Pl, <0, 0, 0>)
I("isosurface", Iso, <0.5, 0, 0>)
I("torus", Tor, <2, 0, 0>)
E("sphere", S)
E("box", B)
E("cylinder", C)
E("cone", K)
E("torus", Tor)
E("union", U)
E("union moved", object { U rotate 30 * x translate 1 })
E("intersection plane", Ip)
E("intersection plane moved", Iq)
E("difference", D)
E("merge", M)
E("clipped", Clip)
E("bounded", Bnd)
E("triangle", Tri)
E("mesh", Mesh)
E("plane", Pl)
E("isosurface", Iso)
E("text", Txt)
E("sor", Sor)
#debug "END\n"
