// #fopen/#write/#read/#fclose checked against POV-Ray 3.7's #debug output (fileio.out).
#version 3.7;
#debug "BEGIN\n"
#fopen F "povwall_fileio_test.txt" write
#write (F, "\"text, with comma\",", 5, ",", -2.5e-7, ",", <1, 2, 3>, ",", <1, 2>, ",", 1/3, ",")
#write (F, 123456789, ",", <1, 0.5, 0, 0.25, 1>, "\n", "7 8", " , -9")
#fclose F
#fopen F "povwall_fileio_test.txt" append
#write (F, ",\"last\"")
#fclose F
#fclose F
#fopen F "povwall_fileio_test.txt" read
#declare N = 0;
#declare V = 0;
#while (defined(F))
  #undef V
  #read (F, V)
  #switch (N)
    #case (0) #debug concat("string [", V, "]\n") #break
    #case (3) #debug concat("vector ", vstr(3, V, ",", 0, 6), "\n") #break
    #case (4) #debug concat("uv ", vstr(2, V, ",", 0, 6), "\n") #break
    #case (7) #debug concat("colour ", vstr(5, V, ",", 0, 6), "\n") #break
    #case (10) #debug concat("string [", V, "]\n") #break
    #else #debug concat("float ", str(V, 0, 9), "\n")
  #end
  #declare N = N + 1;
#end
#debug concat("values ", str(N, 0, 0), "\n")
#fopen G "povwall_fileio_test2.txt" write
#write (G, "1, 2")
#fclose G
#declare C = 99;
#fopen G "povwall_fileio_test2.txt" read
#read (G, A, B, C)
#debug concat(str(A, 0, 0), " ", str(B, 0, 0), " ", str(C, 0, 0), "\n")
#ifdef (G) #debug "G open\n" #else #debug "G closed\n" #end
#fopen E "povwall_fileio_test2.txt" write
#fclose E
#fopen E "povwall_fileio_test2.txt" read
#read (E, Z)
#ifdef (Z) #debug "Z set\n" #else #debug "Z unset\n" #end
#ifdef (E) #debug "E open\n" #else #debug "E closed\n" #end
#macro FirstValue() #local Q = "x"; #read (H, Q) Q #end
#fopen H "povwall_fileio_test.txt" read
#debug concat("macro [", FirstValue(), "]\n")
#ifdef (Q) #debug "Q global\n" #else #debug "Q local\n" #end
#fclose H
#debug "END\n"
