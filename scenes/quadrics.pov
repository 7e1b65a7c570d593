// quadrics.pov — general quadrics and transformed primitives:
//   - a cooling tower: a one-sheet hyperboloid clipped by a box, hollowed by
//     a narrower hyperboloid,
//   - a tilted ellipsoid written as a quadric with a cross term,
//   - a dish: a paraboloid clipped by a box, minus the same paraboloid
//     raised a little, on a cone stand,
//   - cones (one lying on its side), an ellipsoid made by scaling a sphere,
//     an elliptic cylinder made by scaling a cylinder,
// on a finite slab. Objects sink slightly into the slab so that no two
// surfaces lie on each other.
//
// Mask comparison (model/povray_test.cpp): the background has red = 0 and
// every pigment has red > 0 with ambient > 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.5, 4.6, -7.8> look_at <0.1, 0.7, 0.4> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 6, -2> color rgb <0.35, 0.3, 0.3> }
background { color rgb <0, 0.03, 0.07> }

// ---------------------------------------------------------- cooling tower
// x^2 + z^2 - 0.25 y^2 - 0.16 < 0: waist radius 0.4 at y = 0
difference {
  intersection {
    quadric { <1, -0.25, 1>, <0, 0, 0>, <0, 0, 0>, -0.16 }
    box { <-2, -1.05, -2>, <2, 0.75, 2> }
  }
  quadric { <1, -0.25, 1>, <0, 0, 0>, <0, 0, 0>, -0.11 }
  pigment { color rgb <0.8, 0.78, 0.72> }
  finish { ambient 0.15 diffuse 0.7 phong 0.2 }
  translate <-0.3, 1.0, 1.2>
}

// ------------------------------------ tilted ellipsoid (xy cross term)
quadric { <1, 4, 2>, <1.5, 0, 0>, <0, 0, 0>, -0.36
  pigment { color rgb <0.9, 0.35, 0.3> }
  finish { ambient 0.12 diffuse 0.7 phong 0.7 phong_size 70 }
  translate <-2.2, 0.3, -0.3>
}

// -------------------------------------------------- dish on a cone stand
// x^2 + z^2 - 0.5 y < 0: the solid inside the paraboloid y = 2 (x^2 + z^2)
union {
  difference {
    intersection {
      quadric { <1, 0, 1>, <0, 0, 0>, <0, -0.5, 0>, 0 }
      box { <-1, -0.1, -1>, <1, 0.5, 1> }
    }
    quadric { <1, 0, 1>, <0, 0, 0>, <0, -0.5, 0>, 0.04 }
    pigment { color rgb <0.45, 0.7, 0.9> }
    finish { ambient 0.12 diffuse 0.7 phong 0.6 phong_size 60 }
    rotate <-35, 0, 0>
    translate <0, 0.85, 0>
  }
  cone { <0, -0.05, 0>, 0.35, <0, 0.9, 0>, 0.06
    pigment { color rgb <0.6, 0.6, 0.65> }
    finish { ambient 0.12 diffuse 0.6 phong 0.3 }
  }
  rotate <0, -25, 0>
  translate <2.0, 0, 1.1>
}

// ------------------------------------------------------------------ cones
cone { <0, -0.05, 0>, 0.45, <0, 1.2, 0>, 0
  pigment { color rgb <0.95, 0.7, 0.2> }
  finish { ambient 0.12 diffuse 0.7 phong 0.5 }
  translate <-1.5, 0, 1.5>
}
cone { <-0.55, 0, 0>, 0.3, <0.55, 0, 0>, 0.12
  pigment { color rgb <0.4, 0.8, 0.45> }
  finish { ambient 0.12 diffuse 0.7 phong 0.5 }
  rotate <0, 40, 0>
  translate <0.6, 0.27, -0.8>
}

// ------------------------------- scaled sphere and scaled cylinder
sphere { <0, 0, 0>, 1
  scale <0.55, 0.3, 0.35>
  rotate <0, -30, 15>
  translate <-0.7, 0.3, -1.0>
  pigment { color rgb <0.75, 0.4, 0.85> }
  finish { ambient 0.12 diffuse 0.7 phong 0.8 phong_size 90 }
}
cylinder { <0, -0.05, 0>, <0, 0.5, 0>, 1
  scale <0.45, 1, 0.22>
  rotate <0, 50, 0>
  translate <1.9, 0, -0.6>
  pigment { color rgb <0.85, 0.5, 0.35> }
  finish { ambient 0.12 diffuse 0.7 phong 0.4 }
}

// ------------------------------------------------------------- the slab
box { <-3.4, -0.4, -1.8>, <3.4, 0, 3.0>
  pigment { color rgb <0.5, 0.52, 0.56> }
  finish { ambient 0.1 diffuse 0.7 }
}
