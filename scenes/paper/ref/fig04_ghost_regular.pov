// Reference for fig04_ghost under ties "regular": A owns the shared top,
// as under "paper", though for another reason. The two tops are cut by
// coincident planes of two cutters (post-order leaves: A's cylinder 0, A's
// top cutter 1, A's bottom cutter 2, B's cylinder 3, B's top cutter 4, B's
// bottom cutter 5). A ray from above the overlap is inside both infinite
// cylinders and both top cutters and leaves the two cutters at the same t.
// The regular key (algorithm.md section 3) sorts leaving events in
// ascending leaf order, so it leaves cutter 1 first: A's top is struck
// first, and B's cutter, left last, is the infinitesimally larger one. A ray
// from below leaves the bottom cutters 2 and 5 the same way. So B's overlap
// with A is removed here, and only the overlap's visible faces (tops and
// bottoms) depend on it: the overlap's volume is hidden either way. (The
// regular key's "the right operand shows" holds for coincident faces of
// solids, which are entered: Fig. 14; coincident faces made by cutters are
// left, and go the other way.)
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
