// Reference for fig13 under ties "regular": the innermost box owns the front: B and C pulled forward.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.0, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
union {
  box { <-1, 0, -0.8>, <1, 1, 0.8> pigment { color rgbf <0.7, 0.9, 1.0, 0.8> } interior { ior 1.2 } }
  box { <-0.6, 0.2, -0.81>, <0.6, 0.8, 0.4> pigment { color rgbf <1.0, 0.6, 0.6, 0.8> } interior { ior 1.4 } }
  box { <-0.3, 0.35, -0.82>, <0.3, 0.65, 0.0> pigment { color rgbf <0.6, 1.0, 0.6, 0.8> } interior { ior 1.6 } }
  finish { ambient 0.05 diffuse 0.3 phong 0.6 phong_size 80 }
  rotate <10, 24, -6>
}
box { <-3, -0.6, 2.5>, <3, 3, 2.7> pigment { color rgb <0.9, 0.9, 0.85> } }
box { <-3, -0.6, -3>, <3, -0.4, 2.5> pigment { color rgb <0.4, 0.45, 0.4> } }
