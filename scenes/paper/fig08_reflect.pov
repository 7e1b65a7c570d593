// Fig. 8: a reflective sphere resting on a plane, with two coloured blocks
// to reflect. The hit point on the mirror rounds to either side of the
// surface; the reflected ray must not strike the sphere it leaves (no
// self-reflection speckle) and no point may shadow itself. Needs reflected
// and shadow rays: until the model has them it renders without reflection.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.0, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
sphere { <0, 0.75, 0>, 0.75
  pigment { color rgb <0.75, 0.78, 0.8> }
  finish { ambient 0.05 diffuse 0.3 phong 0.8 phong_size 120 reflection 0.7 }
  rotate <7, 13, 0>
}
box { <-2.2, 0, 0.9>, <-1.2, 1.2, 1.9> pigment { color rgb <0.9, 0.3, 0.2> } rotate <0, 25, 0> }
box { <1.3, 0, 0.4>, <2.1, 0.8, 1.2> pigment { color rgb <0.25, 0.7, 0.3> } rotate <0, -20, 0> }
plane { y, 0
  pigment { color rgb <0.7, 0.68, 0.6> }
  finish { ambient 0.1 diffuse 0.7 reflection 0.1 }
}
