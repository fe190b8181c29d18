// Expression semantics checked against POV-Ray 3.7's own #debug output (expressions.out).
#debug "BEGIN\n"
#declare A = 3;
#declare V = <1, 2, 3> * 2 + 1;
#debug concat(vstr(3, V, ",", 0, 3), "\n")
#debug concat(str(A * 2 - 1 / 4, 0, 6), " ", str(-A + 10, 0, 2), "\n")
#debug concat(str(mod(-7, 3), 0, 3), " ", str(div(-7, 2), 0, 3), " ", str(int(-2.5), 0, 3), "\n")
#debug concat(str(floor(-2.5), 0, 3), " ", str(ceil(2.1), 0, 3), " ", str(pow(2, 10), 0, 1), "\n")
#debug concat(str(vlength(<3, 4, 0>), 0, 4), " ", str(vdot(x, y + x), 0, 2), "\n")
#debug concat(vstr(3, vcross(x, y), ",", 0, 2), " ", vstr(3, vnormalize(<0, 3, 4>), ",", 0, 3), "\n")
#debug concat(vstr(3, vrotate(x, <0, 0, 90>), ",", 0, 4), "\n")
#debug concat(vstr(3, vaxis_rotate(x, y, 90), ",", 0, 4), "\n")
#debug concat(str(select(-1, 10, 20), 0, 0), str(select(0, 10, 20, 30), 0, 0), str(select(1, 10, 20), 0, 0), "\n")
#debug concat(str(((1 < 2) & (3 > 2)), 0, 0), str((1 = 1.0), 0, 0), str(!0, 0, 0), str((2 != 2), 0, 0), str((0 | 1), 0, 0), "\n")
#debug concat(str((A > 2 ? 7 : 8), 0, 0), "\n")
#debug concat(str(<1, 2, 3>.y, 0, 1), " ", str((V).z, 0, 1), " ", str(atan2(1, 1), 0, 6), "\n")
#declare C = rgb <0.2, 0.4, 0.6>;
#debug concat(str(C.red, 0, 2), str(C.green, 0, 2), str(C.blue, 0, 2), "\n")
#declare F = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#debug concat(str(F.filter, 0, 2), " ", str(F.transmit, 0, 2), "\n")
#declare G = rgbt <1, 1, 1, 0.25>;
#debug concat(str(G.filter, 0, 2), " ", str(G.transmit, 0, 2), "\n")
#debug concat(str(degrees(pi), 0, 3), " ", str(radians(180), 0, 5), "\n")
#debug concat(str(max(1, 5, 3), 0, 0), str(min(4, 2, 8), 0, 0), " ", str(abs(-2.5), 0, 1), "\n")
#debug concat(str(sqrt(2), 0, 8), " ", str(exp(1), 0, 8), " ", str(ln(10), 0, 8), " ", str(log(1000), 0, 3), "\n")
#debug concat(str(123.456, 8, 2), "|", str(5, -4, 0), "|", str(0.5, 0, -1), "\n")
#debug concat(strupr("abc"), strlwr("DeF"), substr("hello", 2, 3), chr(65), str(asc("a"), 0, 0), str(strlen("four"), 0, 0), "\n")
#debug concat(str(val("2.5") * 2, 0, 1), "\n")
#debug concat(vstr(2, <1, 2>, "/", 0, 0), " ", vstr(5, <1, 2, 3, 4, 5>, " ", 0, 0), "\n")
#debug concat(str(< 1 2 3 >.z, 0, 0), " ", vstr(3, < -1 0 0 >, ",", 0, 0), "\n")
#debug concat(str(true + yes + on, 0, 0), str(false + no + off, 0, 0), "\n")
#debug concat(str(2 * 3 + 4 * 5, 0, 0), " ", str(2 - 3 - 4, 0, 0), " ", str(8 / 2 / 2, 0, 0), " ", str(-2 * -3, 0, 0), "\n")
#debug "END\n"
