// Henyey-Greenstein scattering at the edges of its range (eccentricity 1, -1 and 0.99)
// and Mie murky, a light inside the media, rays grazing the container's surface: no NaN,
// as POV-Ray (method 3, jitter 0).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 1, 0> angle 50 }
light_source { <0, 1, 3> color rgb 1 }
light_source { <0, 1, -3> color rgb 0.5 }
plane { y, 0 pigment { rgb 0.5 } }
sphere { <-1.6, 1, 0>, 0.75 hollow pigment { rgbt 1 }
  interior { media { scattering { 5, rgb 0.6 eccentricity 1 } } } }
sphere { <0, 1, 0>, 0.75 hollow pigment { rgbt 1 }
  interior { media { scattering { 5, rgb 0.6 eccentricity -1 } } } }
sphere { <1.6, 1, 0>, 0.75 hollow pigment { rgbt 1 }
  interior { media { scattering { 5, rgb 0.6 eccentricity 0.99 } }
             media { scattering { 3, rgb 0.2 } } } }
box { <-3, 2, 2.5>, <3, 3, 3.5> hollow pigment { rgbt 1 }
  interior { media { scattering { 1, rgb 0.5 } } } }
