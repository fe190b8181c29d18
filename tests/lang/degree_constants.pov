// radians() and degrees() to 20 digits, in the scene language (times and divided by
// POV-Ray's M_PI_180) and in functions (times M_PI / 180 and 180 / M_PI): for some
// angles (23, 46.5, 59) the product differs in the last bit from x * pi / 180.
#version 3.7;
#declare FR = function(x) { radians(x) }
#declare FD = function(x) { degrees(x) }
#debug "BEGIN\n"
#for (A, 0, 12)
  #declare X = 23 + A * 3.25;
  #debug concat(str(radians(X), 0, 20), " ", str(FR(X), 0, 20), "\n")
  #debug concat(str(degrees(X / 50), 0, 20), " ", str(FD(X / 50), 0, 20), "\n")
#end
#debug concat(str(radians(59), 0, 20), " ", str(degrees(1.1), 0, 20), "\n")
#debug "END\n"
