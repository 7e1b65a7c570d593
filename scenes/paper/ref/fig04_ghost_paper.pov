// Reference for fig04_ghost under ties "paper": A's faces are struck first
// at equal t, so A shows on the shared top; B's overlap with A removed.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.2, -4.6> look_at <0, 0.45, 0> angle 46 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
background { color rgb <0.08, 0.12, 0.45> }
#declare RA = 0.9;
#declare RB = 0.7;
union {
  difference {
    quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -RA*RA }
    plane { -y, -1 }
    plane { y, 0 }
    translate <-0.55, 0, 0>
    pigment { color rgb <0.85, 0.2, 0.15> }
  }
  difference {
    quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -RB*RB translate <0.6, 0, 0> }
    quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -RA*RA translate <-0.55, 0, 0> }
    plane { -y, -1 }
    plane { y, 0 }
    pigment { color rgb <0.2, 0.75, 0.25> }
  }
  finish { ambient 0.15 diffuse 0.75 }
  rotate <9, 23, -7>
}
