// trace() on cones: the hit points and normals to 20 digits, as POV-Ray meets a cone in the frame of
// its full cone's tip (the first point its apex, the wider end on top).
#version 3.7;
#declare N = <0,0,0>;
#declare C1 = cone { <0.3, 0.1, 0.2>, 0.7, <1, 2, 3>, 0.2 }
#declare C2 = cone { <0.3, 0.1, 0.2>, 0.2, <1, 2, 3>, 0.9 }
#declare C3 = cone { <0.3, 0.1, 0.2>, 0, <1, 2, 3>, 0.9 open }
#declare C4 = cone { <0.3, 0.1, 0.2>, 0.5, <1, 2, 3>, 0.5 }
#declare D = <0.47409982303501752021, 0, 0.88047109992217531538>;
#debug "BEGIN\n"
#for (I, 1, 4)
  #declare C = array[4] { C1, C2, C3, C4 }
  #declare P = trace(C[I - 1], <-3, 1, -5>, D, N);
  #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
  #declare P = trace(C[I - 1], <-3, 1.3, 1.3>, x, N);
  #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
  #declare P = trace(C[I - 1], <0.5, 5, 1.3>, -y, N);
  #debug concat(vstr(3, P, ",", 0, 20), "\n") #debug concat(vstr(3, N, ",", 0, 20), "\n")
#end
#debug "END\n"
