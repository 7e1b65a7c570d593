// nested_glass.pov — transparent solids inside each other with different
// indices: a glass block holding a water sphere holding an air bubble. The
// refracted rays carry their leaf flags through every interface, so each
// crossing names the media on both sides (BORDER from, to).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.6, -4.5> look_at <0, 0.6, 0> angle 40 right x*4/3 }
light_source { <-2.5, 5, -4> color rgb <1, 1, 1> }
background { color rgb <0.12, 0.1, 0.08> }

box { <-3, -0.2, -2>, <3, 0, 4> pigment { color rgb <0.7, 0.45, 0.3> } }
box { <-3, 0, 2.5>, <3, 2.5, 2.7> pigment { color rgb <0.3, 0.5, 0.7> } }
cylinder { <-1.6, 0, 1.6>, <-1.6, 1.8, 1.6>, 0.15 pigment { color rgb <0.9, 0.8, 0.2> } }
cylinder { <1.4, 0, 1.8>, <1.4, 1.6, 1.8>, 0.15 pigment { color rgb <0.8, 0.2, 0.2> } }
union {
  box { <-0.9, 0, -0.9>, <0.9, 1.6, 0.9> pigment { color rgbf <0.9, 0.95, 1, 0.92> } interior { ior 1.5 } }
  sphere { <0, 0.8, 0>, 0.65 pigment { color rgbf <0.8, 0.9, 1, 0.95> } interior { ior 1.33 } }
  sphere { <0.15, 0.9, -0.1>, 0.25 pigment { color rgbf <1, 1, 1, 0.98> } interior { ior 1.0 } }
  finish { ambient 0.02 diffuse 0.05 phong 0.6 phong_size 60 }
  rotate <0, 25, 0>
}
