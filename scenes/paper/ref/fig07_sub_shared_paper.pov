// Reference for fig07 under ties "paper": films over the slot, seen from
// outside: from outside the solid looks like the whole box.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.0, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
box { <-1, 0, -0.8>, <1, 1, 0.8>
  pigment { color rgb <0.85, 0.65, 0.3> }
  finish { ambient 0.15 diffuse 0.75 }
  rotate <11, 27, -7>
}
