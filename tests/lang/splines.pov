// Splines checked against POV-Ray 3.7's #debug output (splines.out): every kind, inside
// and outside the points' range, knots, repeated t, mixed widths, copies, S(p, kind).
#version 3.7;
#debug "BEGIN\n"
#macro Show(Name, V) #debug concat(Name, " ", vstr(3, <0,0,0> + V, " ", 0, 17), "\n") #end
#declare Pts = spline {
  -1, <0.3, 1, -2>
  0.25 <1.7, -0.2, 0.5>, 0.6, <0.1, 2.9, 1>
  1.4, <2, 0.7, -0.3>, 3, <-1, 0.1, 0.2>,
  4.2, <0.5, 0.5, 5>
}
#declare L = spline { Pts linear_spline }
#declare Q = spline { Pts quadratic_spline }
#declare C = spline { Pts cubic_spline }
#declare N = spline { Pts natural_spline }
#declare I = 0;
#while (I < 17)
  #declare P = -1.6 + I * 0.37;
  Show(concat("L ", str(P, 0, 2)), L(P))
  Show(concat("Q ", str(P, 0, 2)), Q(P))
  Show(concat("C ", str(P, 0, 2)), C(P))
  Show(concat("N ", str(P, 0, 2)), N(P))
  #declare I = I + 1;
#end
Show("knot L", L(0.6)) Show("knot Q", Q(1.4)) Show("knot C", C(3)) Show("knot N", N(0.25))
Show("end L", L(4.2)) Show("end C", C(4.2)) Show("start N", N(-1))
Show("as natural", L(2.2, natural_spline)) Show("still linear", L(2.2))
#declare D = spline { 0, <1, 1> 1, <2, 2> 2, <3, 3> 1, <7, 7> 2, <9, 9> 0, <5, 5> }
Show("dup 0", D(0)) Show("dup 1", D(1)) Show("dup 2", D(2))
#declare M = spline { 0, <1, 2, 3> 1, <4, 5> }
Show("mixed", M(1)) Show("mixed half", M(0.5))
#declare Two = spline { cubic_spline 0, <1, 3> 2, <5, 7> }
Show("cubic two", Two(0.3))
#declare Three = spline { cubic_spline 0, 1 1, 4 2, 9 }
Show("cubic three", Three(1.7))
#declare One = spline { natural_spline 5, <1, 2, 3> }
Show("one point", One(-3))
#declare F = spline { 0, 2 1, 6 }
#debug concat("float spline ", vstr(2, F(0.25), " ", 0, 17), " y ", str(F(0.75).y, 0, 17), "\n")
#declare Col = spline { 0, <1, 0, 0, 0, 1> 1, <0, 1, 0, 0.5, 0> }
#debug concat("colour ", vstr(5, Col(0.5), " ", 0, 6), " ", str(Col(0.25).transmit, 0, 6), "\n")
#declare Copy = spline { Q 5, <1, 1, 1> }
Show("copy", Copy(4.6)) Show("original", Q(4.6))
#debug "END\n"
