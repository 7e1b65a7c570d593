// Reference for fig15 under ties "paper", front layer: the sphere split by
// the cut plane into the part below it (the lamina's colour: rays entering
// there see the lamina from outside) and the cap above it (magenta: rays
// entering there pass inside and see what is behind, ref/fig15_lamina_back.pov).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.6, -4.6> look_at <0, 0.2, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
union {
  intersection { sphere { <0, 0, 0>, 1 } plane { y, 0.35 } pigment { color rgb <0.95, 0.75, 0.25> } }
  intersection { sphere { <0, 0, 0>, 1 } plane { -y, -0.35 } pigment { color rgb <1, 0, 1> } }
  finish { ambient 0.15 diffuse 0.75 phong 0.4 }
  rotate <-12, 15, 6>
}
box { <-3.5, -1.2, 1.6>, <3.5, 3, 1.8>
  pigment { color rgb <0.55, 0.6, 0.7> }
  finish { ambient 0.1 diffuse 0.5 reflection 0.6 }
  rotate <0, 8, 0>
}
box { <-3.5, -1.4, -3>, <3.5, -1.2, 1.6> pigment { color rgb <0.45, 0.4, 0.35> } }
