// Fig. 16: a simple scene with a transparent object: a glass sphere added
// to a glass box (they overlap; the sphere owns the overlap) in front of
// coloured blocks. Needs transmitted rays: until the model has them the
// glass renders opaque.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.0, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
union {
  box { <-0.9, 0, -0.5>, <0.5, 0.7, 0.5> pigment { color rgbf <0.8, 0.95, 1.0, 0.85> } interior { ior 1.3 } }
  sphere { <0.3, 0.75, 0>, 0.6 pigment { color rgbf <1.0, 0.9, 0.8, 0.85> } interior { ior 1.5 } }
  finish { ambient 0.05 diffuse 0.3 phong 0.6 phong_size 80 }
  rotate <0, 20, 0>
}
box { <-2.5, 0, 1.2>, <-1.5, 1.5, 2.2> pigment { color rgb <0.9, 0.3, 0.2> } }
box { <-0.5, 0, 1.5>, <0.5, 1.2, 2.5> pigment { color rgb <0.25, 0.7, 0.3> } }
box { <1.4, 0, 1.1>, <2.4, 1.0, 2.1> pigment { color rgb <0.3, 0.35, 0.85> } }
plane { y, 0 pigment { color rgb <0.7, 0.68, 0.6> } }
