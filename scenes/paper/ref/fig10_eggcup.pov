// Reference for fig10 (both tie policies): the slabs overlap instead of
// touching (a later slab owns the overlap), so no two layer faces coincide.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.6, -5.2> look_at <0, 1.0, 0> angle 40 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
difference {
  intersection {
  union {
    box { <-1.1, -0.1, -1.1>, <1.1, 0.5, 1.1> pigment { color rgb <0.55, 0.33, 0.16> } }
    box { <-1.1, 0.3, -1.1>, <1.1, 0.9, 1.1> pigment { color rgb <0.85, 0.7, 0.45> } }
    box { <-1.1, 0.7, -1.1>, <1.1, 1.3, 1.1> pigment { color rgb <0.35, 0.2, 0.1> } }
    box { <-1.1, 1.1, -1.1>, <1.1, 1.7, 1.1> pigment { color rgb <0.55, 0.33, 0.16> } }
    box { <-1.1, 1.5, -1.1>, <1.1, 2.1, 1.1> pigment { color rgb <0.85, 0.7, 0.45> } }
    box { <-1.1, 1.9, -1.1>, <1.1, 2.3, 1.1> pigment { color rgb <0.35, 0.2, 0.1> } }
  }
  union {
    cone { <0, -0.1, 0>, 0.75, <0, 0.3, 0>, 0.22 }
    cylinder { <0, 0.2, 0>, <0, 1.2, 0>, 0.22 }
    intersection { sphere { <0, 1.65, 0>, 0.72 } plane { y, 2.2 } }
    pigment { color rgb <0.6, 0.45, 0.3> }
  }
  }
  sphere { <0, 1.72, 0>, 0.6 }
  finish { ambient 0.15 diffuse 0.75 phong 0.2 }
  rotate <8, 17, -5>
}
