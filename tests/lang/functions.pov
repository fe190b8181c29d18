// The function language checked against POV-Ray 3.7's #debug output (functions.out).
#version 3.7;
#include "math.inc"
#debug "BEGIN\n"
#macro Show(Name, V) #debug concat(Name, " ", str(V, 0, 17), "\n") #end
#declare A = 2;
#declare F = function(a, b) { a * A + b / 3 - 1 }
#declare A = 7;  // captured when F was declared
Show("captured", F(1.5, 2))
#declare G = function { x + y * 10 + z * 100 }
Show("xyz", G(1, 2, 3))
#declare UV = function { u + v }
Show("uv", UV(1, 2, 3))
#declare Missing = function(x) { x * y + 5 }
Show("missing y", Missing(4))
#declare Named = function(z, y, x) { x * 100 + y * 10 + z }
Show("named", Named(1, 2, 3))
#declare Prec = function { x + y * z - x / y * z + (x < y) + (y = 2) * 10 | 0 & 1 }
Show("precedence", Prec(1, 2, 3))
#declare Cmp = function(a, b) { (a < b) + (a <= b) * 2 + (a > b) * 4 + (a >= b) * 8 + (a = b) * 16 + (a != b) * 32 }
Show("cmp 1 2", Cmp(1, 2)) Show("cmp 2 2", Cmp(2, 2)) Show("cmp 3 2", Cmp(3, 2))
#declare NaN = function(a) { sqrt(a) }
#declare CmpNaN = function(a) { Cmp(NaN(a), 0) }
Show("cmp nan", CmpNaN(-1))
#declare MinMax = function(a) { min(3, NaN(a), 1) * 10 + max(1, NaN(a), 2) }
Show("min max nan", MinMax(-4))
#declare Min4 = function(a) { min(5, a, 7, 4) }
Show("min 4", Min4(3))
#declare Ints = function(a) { int(a) + div(-7, 2) * 1000 }
Show("int", Ints(-2.7)) Show("int big", Ints(3e10))
#declare Sel = function(a) { select(a, 1, 2) * 10 + select(a, 1, 2, 3) }
Show("select -", Sel(-1)) Show("select 0", Sel(0)) Show("select +", Sel(5)) Show("select nan", Sel(NaN(-1)))
#declare Fns = function(a) { mod(a, 3) + abs(-a) * 10 + floor(a / 2) * 100 + ceil(a / 4) * 1000 + pow(a, 0.5) + log(100) + ln(1) + exp(0) + atan2(1, -1) + degrees(pi) + radians(180) }
Show("builtins", Fns(7.5))
#declare Trig = function { sin(x) + cos(y) + tan(z) + asin(0.5) + acos(0.5) + atan(2) + sinh(x) + cosh(y) + tanh(z) + asinh(1) + acosh(2) + atanh(0.5) }
Show("trig", Trig(0.3, 0.7, 1.1))
#declare Chain = function { G(x, y, z) * 2 + F(x, y) }
Show("calls", Chain(1, 2, 3))
Show("f_sqr clip", f_sqr(3) + clip(5, 0, 2) * 100 + sgn(-3) * 1000 + clamp(7, 0, 4) * 10000)
Show("noise", f_noise3d(1.3, -2.7, 0.4)) Show("snoise", f_snoise3d(0.5, 0.5, 0.5))
Show("f_r f_sphere", f_r(1, 2, 2) + f_sphere(1, 2, 2, 0.5) * 10)
Show("f_th f_ph", f_th(1, 0, 1) + f_ph(1, 1, 0) * 10)
#declare Gran = function { pattern { granite } }
Show("pattern granite", Gran(1.3, -2.7, 0.4))
#declare Grad = function { pattern { gradient x } }
Show("gradient 1", Grad(1, 0, 0)) Show("gradient 1.25", Grad(1.25, 0, 0)) Show("gradient -0.25", Grad(-0.25, 0, 0))
#declare Pig = function { pigment { gradient x color_map { [0 rgb <0, 0.2, 1>] [1 rgb <1, 0.6, 0>] } } }
#declare PigUse = function { Pig(x, y, z).red + Pig(x, y, z).green * 10 + Pig(x, y, z).gray * 100 }
Show("pigment", PigUse(0.3, 0, 0))
// MegaPOV's .hf member, kept by POV-Ray 3.7: (red + green / 255) x 0.996093.
#declare PigHf = function { Pig(x, y, z).hf }
Show("pigment hf", PigHf(0.3, 0, 0))
#declare C = Pig(0.6, 0, 0);
#debug concat("pigment call ", vstr(5, C, " ", 0, 9), "\n")
#declare S = function { spline { linear_spline 0, <0, 1, 2>, 1, <2, 3, 4> } }
#declare SU = function { S(x).y + S(x).z * 10 }
Show("spline", SU(0.25, 0, 0))
#debug concat("spline call ", vstr(3, S(0.5), " ", 0, 9), "\n")
#declare Tr = function { transform { scale 2 translate x rotate 30 * z } }
#declare TrUse = function { Tr(x, y, z).x + Tr(x, y, z).y * 10 + Tr(x, y, z).z * 100 }
Show("transform", TrUse(1, 2, 3))
#debug concat("transform call ", vstr(3, Tr(1, 2, 3), " ", 0, 12), "\n")
#declare Sums = function(a) { sum(i, 1, a, i * i) + prod(k, 0.5, 3, k) * 1000 + sum(j, 3, 1, 9) }
Show("sum prod", Sums(4))
#declare Nested = function { sum(i, 1, 3, sum(j, 1, i, i * 10 + j + x)) }
Show("nested sum", Nested(0.5, 0, 0))
#declare Shadow = function { sum(x, 1, 2, x) }
Show("shadowed counter", Shadow(7, 0, 0))
// functions.inc's f_helix1 (internal 25) and f_rounded_box (internal 60).
#declare Helix = function { internal(25) }
#declare RBox = function { internal(60) }
Show("helix circle", Helix(0.7, 0.3, 0.4, 2, 1.5, 0.1, 0.6, 1, 1, 0))
Show("helix axis", Helix(0, 0.2, 0, 3, 2, 0.1, 0.5, 1, 1, 0))
Show("helix diamond", Helix(-0.5, 1.1, 0.2, 1, 0.5, 0.2, 0.4, 0.8, 2, 0))
Show("helix square turned", Helix(0.3, -0.4, -0.6, 2, 1, 0.1, 0.6, 1, 0, 30))
Show("helix rounded", Helix(0.2, 2.5, 0.9, 4, 3, 0.05, 0.8, 2, 0.5, 15))
Show("rounded box out", RBox(1.5, 0.2, -2, 0.1, 1, 0.5, 0.8))
Show("rounded box in", RBox(0.1, 0.2, 0.3, 0.1, 1, 0.5, 0.8))
Show("rounded box corner", RBox(-1.2, 0.7, 0.9, 0.25, 1, 0.5, 0.8))
Show("rounded box thin", RBox(0.3, 0.05, 0, 0.5, 1, 0.2, 0.8))
#debug "END\n"
