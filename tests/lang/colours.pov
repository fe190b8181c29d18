// Colour forms and colors.inc, checked against POV-Ray 3.7's #debug output (colours.out).
#include "colors.inc"
#debug "BEGIN\n"
#macro Show(C) #debug concat(vstr(5, C, ",", 0, 4), "\n") #end
#declare C1 = color red 1 green 0.5;
Show(C1)
Show(rgb <0.1, 0.2, 0.3>)
Show(rgbf <0.1, 0.2, 0.3, 0.4>)
Show(rgbt <0.1, 0.2, 0.3, 0.4>)
Show(rgb 0.5)
Show(color rgb <1, 0, 0> filter 0.5)
Show(Red)
Show(SkyBlue * 0.5)
Show(Orange)
Show(Gray50)
Show(Clear)
Show(color Red + Blue)
Show(colour rgbft <1, 2, 3, 4, 5> transmit 0.25)
#declare Mix = (Red + Green) / 2;
Show(Mix)
#debug concat(str(Orange.green, 0, 4), " ", str(Gray50.gray, 0, 4), "\n")
#debug "END\n"
