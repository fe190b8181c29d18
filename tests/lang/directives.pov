// Directive semantics checked against POV-Ray 3.7's #debug output (directives.out).
#version 3.7;
#debug "BEGIN\n"
#declare I = 0;
#while (I < 3) #debug str(I, 0, 0) #declare I = I + 1; #end
#debug "\n"
#for (J, 5, 1, -2) #debug str(J, 0, 0) #end
#debug "\n"
#for (J, 0, 1, 0.25) #debug concat(str(J, 0, 2), " ") #end
#debug "\n"
#macro Twice(N) (N * 2) #end
#macro SetTo(Var, Val) #declare Var = Val; #end
#macro Counter(Var) #local Tmp = Var + 1; #declare Var = Tmp; #end
#declare K = 1; SetTo(K, 42) Counter(K)
#debug concat(str(K, 0, 0), " ", str(Twice(Twice(3)), 0, 0), "\n")
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#debug concat(str(Fact(6), 0, 0), "\n")
#ifdef (Tmp) #debug "leaked\n" #else #debug "scoped\n" #end
#ifndef (Nope) #debug "nope undefined\n" #end
#declare S = 2;
#switch (S)
  #case (1) #debug "one\n" #break
  #range (2, 3) #debug "two-three\n"
  #case (4) #debug "fallthrough\n" #break
  #else #debug "else\n"
#end
#switch (9) #case (1) #debug "no\n" #else #debug "switch-else\n" #end
#if (0) #debug "a\n" #elseif (0) #debug "b\n" #elseif (1) #debug "c\n" #else #debug "d\n" #end
#if (1) #if (0) #debug "x\n" #else #debug "nested\n" #end #end
#declare Arr = array[2][3] {{1, 2, 3}, {4, 5, 6}}
#debug concat(str(Arr[1][2], 0, 0), str(dimension_size(Arr, 1), 0, 0), str(dimension_size(Arr, 2), 0, 0), str(dimensions(Arr), 0, 0), "\n")
#declare B = array[3]
#declare B[1] = 7;
#debug concat(str(defined(B[0]), 0, 0), str(defined(B[1]), 0, 0), str(B[1], 0, 0), "\n")
#declare Str = concat("a", "b", str(3, 0, 0));
#debug concat(Str, "\n")
#undef Str
#ifdef (Str) #debug "still\n" #else #debug "undefined\n" #end
#local L = 5;
#debug concat(str(L, 0, 0), " ", str(version, 0, 1), "\n")
#declare R = seed(12345);
#debug concat(str(rand(R), 0, 10), " ", str(rand(R), 0, 10), " ", str(rand(R), 0, 10), "\n")
#declare R2 = seed(-1);
#debug concat(str(rand(R2), 0, 10), "\n")
#debug "END\n"
