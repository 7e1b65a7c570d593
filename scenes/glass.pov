// glass.pov — a glass sphere over a checkerboard built by CSG: the board's
// squares are (x-stripes & z-stripes) | (the other x- & z-stripes), each
// stripe the intersection of two planes, so the whole board is 37 leaves.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 2.6, -4.6> look_at <0, 0.3, 0> angle 40 right x*4/3 }
light_source { <-3, 6, -3> color rgb <1, 1, 1> }
background { color rgb <0.1, 0.12, 0.2> }

#declare XA = union {
  intersection { plane { -x, 2 } plane { x, -1 } }
  intersection { plane { -x, 0 } plane { x, 1 } }
  intersection { plane { -x, -2 } plane { x, 3 } }
}
#declare XB = union {
  intersection { plane { -x, 3 } plane { x, -2 } }
  intersection { plane { -x, 1 } plane { x, 0 } }
  intersection { plane { -x, -1 } plane { x, 2 } }
}
#declare ZA = union {
  intersection { plane { -z, 2 } plane { z, -1 } }
  intersection { plane { -z, 0 } plane { z, 1 } }
  intersection { plane { -z, -2 } plane { z, 3 } }
}
#declare ZB = union {
  intersection { plane { -z, 3 } plane { z, -2 } }
  intersection { plane { -z, 1 } plane { z, 0 } }
  intersection { plane { -z, -1 } plane { z, 2 } }
}
union {
  box { <-3, -0.25, -3>, <3, -0.02, 3> pigment { color rgb <0.9, 0.9, 0.85> } }   // just below the squares: no shared face
  intersection {
    box { <-3, -0.25, -3>, <3, 0, 3> }
    union {
      intersection { object { XA } object { ZA } }
      intersection { object { XB } object { ZB } }
    }
    pigment { color rgb <0.15, 0.2, 0.5> }
  }
}
sphere { <0.2, 0.8, 0>, 0.8
         pigment { color rgbf <0.95, 1, 0.95, 0.9> }
         finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 80 reflection 0.08 }
         interior { ior 1.5 } }
