// trace() on cylinders: the hit points and normals to 20 digits, as POV-Ray meets a cylinder in its
// frame (from the second point towards the first).
#version 3.7;
#declare N = <0,0,0>;
#declare C1 = cylinder { <0.3, 0.1, 0.2>, <0.3, 0.1, 3.7>, 0.7 }
#declare C2 = cylinder { <0.3, 0.1, 0.2>, <0.3, 3.1, 0.2>, 0.7 }
#declare C3 = cylinder { <0.3, 0.1, 0.2>, <1, 2, 3>, 0.7 }
#declare C4 = cylinder { <0.3, 0.1, 0.2>, <1, 2, 3>, 1 }
#declare C5 = cylinder { <0, 0, 0>, <1, 2, 3>, 1 }
#declare D = <0.47409982303501752021, 0, 0.88047109992217531538>;
#debug "BEGIN\n"
#declare P = trace(C1, <-3, 1, 1.5>, x, N); #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
#declare P = trace(C2, <-3, 1.3, 0.31>, x, N); #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
#declare P = trace(C3, <-3, 1, -5>, D, N); #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
#declare P = trace(C4, <-3, 1, -5>, D, N); #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
#declare P = trace(C5, <-3, 1, -5>, D, N); #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
#declare P = trace(C3, <-3, 1, 1.3>, x, N); #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
#debug "END\n"
