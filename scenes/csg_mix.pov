// csg_mix.pov — every CSG operation and object reuse:
//   - the classic CSG-tree solid: (cube ∩ sphere) − (three axis cylinders),
//   - a lens: the intersection of two spheres,
//   - a merged cross of two cylinders with a ball hub,
//   - a #declare'd post (a cylinder with a cone-shaped cup carved in its
//     top) reused three times through object {},
//   - a cone sliced by a tilted box,
// on a finite slab. Objects sink slightly into the slab so that no two
// surfaces lie on each other.
//
// Mask comparison (model/povray_test.cpp): the background has red = 0 and
// every pigment has red > 0 with ambient > 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <-0.8, 4.4, -8.2> look_at <0.15, 0.55, 0.5> angle 44 right x*4/3 up y }
light_source { <-6, 9, -5> color rgb <1, 1, 1> }
light_source { <7, 5, -4> color rgb <0.3, 0.3, 0.35> }
background { color rgb <0, 0.04, 0.05> }

// ---------------------------------------- (cube ∩ sphere) − cylinders
difference {
  intersection {
    box { <-1, -1, -1>, <1, 1, 1> pigment { color rgb <0.85, 0.25, 0.2> } }
    sphere { <0, 0, 0>, 1.32 pigment { color rgb <0.2, 0.35, 0.85> } }
  }
  union {
    cylinder { <-1.6, 0, 0>, <1.6, 0, 0>, 0.52 }
    cylinder { <0, -1.6, 0>, <0, 1.6, 0>, 0.52 }
    cylinder { <0, 0, -1.6>, <0, 0, 1.6>, 0.52 }
    pigment { color rgb <0.3, 0.8, 0.3> }
  }
  finish { ambient 0.12 diffuse 0.75 phong 0.5 phong_size 40 }
  scale 0.75
  rotate <0, -30, 0>
  translate <0.2, 0.72, 0.2>
}

// ----------------------------------------------------------------- lens
intersection {
  sphere { <0, 0, -0.9>, 1.2 }
  sphere { <0, 0,  0.9>, 1.2 }
  pigment { color rgb <0.6, 0.85, 0.9> }
  finish { ambient 0.15 diffuse 0.6 phong 0.9 phong_size 150 reflection 0.15 }
  rotate <0, 35, 0>
  translate <-2.1, 0.62, -0.6>
}

// ---------------------------------------------- merged cross with a hub
merge {
  cylinder { <-0.9, 0, 0>, <0.9, 0, 0>, 0.16 }
  cylinder { <0, 0, -0.9>, <0, 0, 0.9>, 0.16 }
  cylinder { <0, -0.5, 0>, <0, 0.5, 0>, 0.12 }
  sphere { <0, 0, 0>, 0.3 }
  pigment { color rgb <0.9, 0.75, 0.2> }
  finish { ambient 0.12 diffuse 0.7 phong 0.7 phong_size 80 }
  rotate <0, 20, 0>
  translate <2.15, 0.55, -0.6>
}

// ----------------------------------------------- a post, used three times
#declare Post = difference {
  cylinder { <0, -0.05, 0>, <0, 1.1, 0>, 0.28 }
  cone { <0, 0.75, 0>, 0, <0, 1.3, 0>, 0.3 }
  pigment { color rgb <0.7, 0.5, 0.85> }
  finish { ambient 0.12 diffuse 0.7 phong 0.4 }
}
object { Post translate <-0.9, 0, 2.1> }
object { Post scale <1, 1.4, 1> translate <0.6, 0, 2.4> }
object { Post scale <1.2, 0.8, 1.2> translate <2.1, 0, 1.9> }

// ------------------------------------------------- a cone cut by a box
intersection {
  cone { <0, -0.05, 0>, 0.7, <0, 1.6, 0>, 0.05 }
  box { <-1, -1, -1>, <1, 0.9, 1> rotate <0, 0, 25> translate <0, 0.1, 0> }
  pigment { color rgb <0.3, 0.75, 0.55> }
  finish { ambient 0.12 diffuse 0.7 phong 0.5 }
  translate <-2.5, 0, 1.3>
}

// ------------------------------------------------------------- the slab
box { <-3.6, -0.4, -1.9>, <3.6, 0, 3.2>
  pigment { color rgb <0.5, 0.52, 0.55> }
  finish { ambient 0.1 diffuse 0.7 }
}
