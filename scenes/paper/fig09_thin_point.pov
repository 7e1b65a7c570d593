// Fig. 9: two spheres subtracted. The inner sphere touches the outer one
// from inside at its top, leaving a single point of zero thickness that
// faces the camera; around it the shell is thinner than one ulp. The shell's
// outer surface must be seen everywhere: no hole into the cavity at the
// thin point (a tolerance makes one).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.0, -4.8> look_at <0, 0.4, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
difference {
  sphere { <0, 0, 0>, 1 }
  sphere { <0, 0.08, 0>, 0.92 }
  pigment { color rgb <0.9, 0.85, 0.7> }
  finish { ambient 0.12 diffuse 0.75 phong 0.3 }
  rotate <-62, 9, 0>
  translate <0, 0.5, 0>
}
