// String relational operators (POV-Ray 3.7's Parse_Rel_String_Term), checked against
// POV-Ray 3.7's own #debug output (string_relations.out).
#version 3.7;
#declare S = "abc";
#declare E = "";
#declare A = array[3] {"x", "y", "zz"}
#macro Name() "abc" #end
#macro Show(Label, V) #debug concat(Label, " ", str(V, 0, 0), "\n") #end
#debug "BEGIN\n"
Show("lt", ("abc" < "abd"))
Show("lt-equal", ("abc" < "abc"))
Show("lt-prefix", ("ab" < "abc"))
Show("le", ("abc" <= "abc"))
Show("le-greater", ("abd" <= "abc"))
Show("eq", (S = "abc"))
Show("eq-case", (S = "ABC"))
Show("ne-empty", (S != ""))
Show("ne-same", (E != ""))
Show("ge", ("b" >= "abc"))
Show("ge-equal", ("" >= ""))
Show("gt-empty", ("" > "a"))
Show("gt", ("a" > ""))
Show("upper-lower", ("A" < "a"))
Show("digits", ("10" < "9"))
Show("space", (" " < "!"))
Show("high", (chr(200) > "z"))
Show("and", (S = "abc" & 1))
Show("and-right", (1 & S = "abc"))
Show("or", (0 | S = "x"))
Show("or-string", (S = "x" | S = "abc"))
Show("ternary", (S = "abc" ? 5 : 6))
Show("not", (!(S = "abc")))
Show("sum", (("a" < "b") + ("b" < "a") + 2))
Show("vector", vlength(<1, 1, 1> * ("a" < "b")) * 100)
Show("function", (concat(S, "d") = "abcd"))
Show("str", (str(1.5, 0, 1) = "1.5"))
Show("substr", (substr(S, 2, 2) > "bb"))
Show("strupr", (strupr(S) = "ABC"))
Show("chr", (chr(65) = "A"))
Show("array", (A[2] > A[1]))
Show("array-eq", (A[0] = "x"))
Show("macro", (Name() = S))
Show("macro-right", (S = Name()))
#declare F = ("a" != "b");
Show("declared", F)
#if (S != "")
  #debug "if taken\n"
#end
#if (E = "")
  #debug "empty taken\n"
#end
#declare I = 0;
#declare T = "";
#while (T != "aaa")
  #declare T = concat(T, "a");
  #declare I = I + 1;
#end
Show("while", I)
#debug concat("strcmp ", str(strcmp("abc", "abd"), 0, 0), " ", str(strcmp("b", "abc"), 0, 0), " ", str(strcmp("ab", "abc"), 0, 0), "\n")
#debug "END\n"
