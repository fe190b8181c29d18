// A #local or #declare whose value is a macro call ending in an array, a function or
// another non-numeric value takes the `;` after the call (POV-Ray's Parse_Declare:
// ALLOW(SEMI_COLON_TOKEN) reads past the called macro's #end), also when the macro
// holding that #local is itself expanded as a #declare's value or as a macro argument.
// Found in t-o-k/POV-Ray-matrices (M_Inv) and t-o-k/POV-Ray-gaussian-blur.
// Checked against POV-Ray 3.7's own #debug output (macro_rvalue_semicolons.out).
#version 3.7;
#declare MM = array[2] {0.2, 0.8};
#macro Ret() MM #end
#macro RetRet() Ret() #end
#macro Fresh(A, B) array[2] {A, B} #end
#macro MkFn(S) function(a) { a * S } #end
#macro MkStr() "txt" #end
#macro MkVec() <1, 2, 3> #end

// Arrays into #local / #declare, with and without `;`.
#macro LocalArr() #local D = Ret(); D #end
#macro LocalArrNoSemi() #local D = Ret() D #end
#macro DeclArr() #declare G = Ret(); G #end
#macro LocalNested() #local D = RetRet(); D #end
#macro LocalFresh() #local D = Fresh(3, 4); #local D[0] = 5; D #end
#macro LocalThen() #local D = Ret(); #local E = D[1] * 10; E #end
// The copy: changing the #local leaves MM as it was.
#macro LocalCopy() #local D = Ret(); #local D[0] = 9; D[0] + MM[0] #end
// Functions into #local / #declare.
#macro LocalFn() #local F = MkFn(2); F(3) #end
#macro LocalFnNoSemi() #local F = MkFn(3) F(3) #end
#macro DeclFn() #declare GF = MkFn(4); GF(3) #end
// Strings and vectors, for company.
#macro LocalStr() #local S = MkStr(); S #end
#macro LocalVec() #local V = MkVec(); V #end

#macro Stmt()
  #local D = Ret();
  #debug concat("statement ", str(D[1], 0, 3), "\n")
#end
#macro Id(A) A #end
#macro First(A) A[0] #end

#debug "BEGIN\n"
#declare W = LocalArr();
#debug concat("LocalArr ", str(W[0], 0, 3), " ", str(W[1], 0, 3), "\n")
#declare W = LocalArrNoSemi();
#debug concat("LocalArrNoSemi ", str(W[1], 0, 3), "\n")
#declare W = DeclArr();
#debug concat("DeclArr ", str(W[1], 0, 3), " ", str(G[0], 0, 3), "\n")
#declare W = LocalNested();
#debug concat("LocalNested ", str(W[1], 0, 3), "\n")
#declare W = LocalFresh();
#debug concat("LocalFresh ", str(W[0], 0, 3), " ", str(W[1], 0, 3), "\n")
#declare X = LocalThen();
#debug concat("LocalThen ", str(X, 0, 3), "\n")
#declare X = LocalCopy();
#debug concat("LocalCopy ", str(X, 0, 3), " ", str(MM[0], 0, 3), "\n")
#local W = LocalArr();
#debug concat("local LocalArr ", str(W[1], 0, 3), "\n")

// As macro arguments.
#declare X = First(LocalArr());
#debug concat("First(LocalArr) ", str(X, 0, 3), "\n")
#declare X = First(LocalArrNoSemi());
#debug concat("First(LocalArrNoSemi) ", str(X, 0, 3), "\n")
#declare X = First(DeclArr());
#debug concat("First(DeclArr) ", str(X, 0, 3), "\n")
#declare W = Id(LocalNested());
#debug concat("Id(LocalNested) ", str(W[1], 0, 3), "\n")
#declare X = Id(LocalFn());
#debug concat("Id(LocalFn) ", str(X, 0, 3), "\n")

// Functions.
#declare X = LocalFn();
#debug concat("LocalFn ", str(X, 0, 3), "\n")
#declare X = LocalFnNoSemi();
#debug concat("LocalFnNoSemi ", str(X, 0, 3), "\n")
#declare X = DeclFn();
#debug concat("DeclFn ", str(X, 0, 3), " ", str(GF(1), 0, 3), "\n")

// Others.
#declare S = LocalStr();
#debug concat("LocalStr ", S, "\n")
#declare V = LocalVec();
#debug concat("LocalVec ", vstr(3, V, ",", 0, 1), "\n")

// As statements, and at top level.
#declare D = Ret();
#debug concat("top ", str(D[1], 0, 3), "\n")
Stmt()
#debug "END\n"
