// Pre-3.1 scenes: a declared float, vector or colour needs no semicolon; its value ends
// at the next directive, which runs after the identifier is declared (macros need 3.1:
// tests/parser/syntax_test.cpp has those, with POV-Ray's 3.1 warning).
// Checked against POV-Ray 3.7's own #debug output (legacy_semicolons.out).
#version 3.0
#declare X = 1
#declare Y = X + 1
#debug "BEGIN\n"
#debug concat("X=", str(X, 0, 0), " Y=", str(Y, 0, 0), "\n")
#declare V = <1, 2, 3> * Y
#if (V.x = 2) #debug "V.x taken\n" #end
#declare W = V
#debug concat("W=", vstr(3, W, ",", 0, 0), "\n")
#declare C = rgb <1, 0.5, 0>
#debug concat("C=", vstr(5, C, ",", 0, 2), "\n")
#declare D = color red 1 green 0.25
#debug concat("D=", vstr(5, D, ",", 0, 2), "\n")
#declare I = 0
#while (I < 3)
  #declare I = I + 1
#end
#debug concat("I=", str(I, 0, 0), "\n")
#declare S = "text"
#debug concat("S=", S, "\n")
#declare Neg = -X
#declare Dot = V.y
#declare P = pi / 2
#debug concat("Neg=", str(Neg, 0, 0), " Dot=", str(Dot, 0, 0), " P=", str(P, 0, 4), "\n")
#declare Last = 7
#debug concat("Last=", str(Last, 0, 0), "\n")
#debug "END\n"
