// Reference for fig14 under ties "regular": each object once, second copy's material.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.0, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
union { sphere { <0, 0.6, 0>, 0.6 pigment { color rgb <0.95, 0.55, 0.2> } }
  finish { ambient 0.15 diffuse 0.75 phong 0.3 } rotate <13, 17, -9> translate <-1.6, 0, 0.5> }
union { box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> pigment { color rgb <0.3, 0.75, 0.9> } }
  finish { ambient 0.15 diffuse 0.75 phong 0.3 } rotate <13, 40, -9> translate <-0.5, 0, -0.3> }
union { cylinder { <0, 0, 0>, <0, 1.1, 0>, 0.5 pigment { color rgb <0.7, 0.85, 0.3> } }
  finish { ambient 0.15 diffuse 0.75 phong 0.3 } rotate <13, 63, -9> translate <0.6, 0, 0.6> }
union { cone { <0, 0, 0>, 0.6, <0, 1.2, 0>, 0.1 pigment { color rgb <0.95, 0.5, 0.8> } }
  finish { ambient 0.15 diffuse 0.75 phong 0.3 } rotate <13, 86, -9> translate <1.7, 0, -0.2> }
