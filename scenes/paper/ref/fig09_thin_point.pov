// Reference for fig09 (both tie policies): the outer sphere alone.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.0, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
sphere { <0, 0, 0>, 1
  pigment { color rgb <0.9, 0.85, 0.7> }
  finish { ambient 0.12 diffuse 0.75 phong 0.3 }
  rotate <-62, 9, 0>
  translate <0, 0.5, 0>
}
