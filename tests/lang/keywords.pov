// Keywords of the scene language that change no image but values, checked against POV-Ray
// 3.7's #debug output (keywords.out): bitwise functions, clock, strings and dates, sRGB
// colours, object extents, vturbulence, internal functions and raw #write formats.
#version 3.7;
global_settings { assumed_gamma 1.0 charset utf8 }
#debug "BEGIN\n"
#macro Show(V) #debug concat(vstr(5, V, ",", 0, 4), "\n") #end
#macro Num(F) #debug concat(str(F, 0, 4), "\n") #end
Num(bitwise_and(12, 10))
Num(bitwise_or(12, 10, 1))
Num(bitwise_xor(12, 10))
Num(clock)
Num(clock_on)
Num(strcmp("abc", "abd"))
Num(strcmp("b", "a"))
Num(strcmp("same", "same"))
Num(file_exists("keywords.pov"))
Num(file_exists("no_such_file.txt"))
#debug concat(datetime(0), "\n")
#debug concat(datetime(1.5, "%Y %j %H"), "\n")
Num((now > 9000))
Show(srgb <0.5, 0.25, 1>)
Show(srgbf <0.5, 0.25, 1, 0.3>)
Show(srgbt <0.5, 0.25, 1, 0.3>)
Show(srgbft <0.5, 0.25, 1, 0.3, 0.6>)
#declare C = rgbt <0.1, 0.2, 0.3, 0.7>;
Num(C.t)
Show(vturbulence(2, 0.5, 6, <1.2, 2.3, 3.4>))
#declare Ball_field = function { internal(61) }  // f_sphere (x, y, z, radius)
Num(Ball_field(0.3, 0.7, 1.1, 0.5))
#declare Noise = function { internal(76) }  // f_noise3d
Num(Noise(0.3, 0.7, 1.1))
// Raw formats: each writes bytes; these spell a string literal that #read gets back.
#fopen Raw "keywords_raw.txt" write
#write (Raw, uint8 <34, 71.6>, sint16be 19019, uint16le 19788, sint32le 1364283214,
       sint8 82, sint16le 21587, uint16be 21846, sint32be 1465473370, uint8 34)
#fclose Raw
#fopen Raw "keywords_raw.txt" read
#read (Raw, S)
#fclose Raw
#debug concat(S, "\n")
#debug "END\n"
