// A colour keyword keeps every term of its expression, as POV-Ray's Parse_Colour: rgb
// with four terms is rgbf, with five rgbft; a declared colour after rgb keeps its filter
// and transmit; rgbt moves its fourth term to transmit whatever follows.
#version 3.7;
#declare Glass = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#declare C = array[10] {
  color rgb <1, 0.5, 0.25, 0.75>, color rgb <1, 0.5, 0.25, 0.75, 0.125>, color rgb <1, 0.5>,
  color rgb Glass, color rgbf <1, 0.5, 0.25, 0.75, 0.125>, color rgbf <1, 0.5, 0.25>,
  color rgbt <1, 0.5, 0.25, 0.75, 0.125>, color rgbt <1, 0.5, 0.25>,
  color rgbft <1, 0.5, 0.25, 0.75>, color rgb 0.5 }
#debug "BEGIN\n"
#for (I, 0, 9)
  #debug concat(vstr(5, C[I], ",", 0, 3), "\n")
#end
#debug "END\n"
