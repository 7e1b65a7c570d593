// Fig. 4 (Wyvill & Trotman): ghost surfaces. Two closed cylinders, each an
// infinite cylinder (quadric) minus two plane half-spaces, added together.
// Their tops lie in the same plane (y = 1) and they overlap, so a ray aimed
// at the top of B also strikes the (infinite) top plane of A at the same t.
// Each top must show its own material: red A, green B; where they overlap the
// tie policy decides, and both decide A: paper strikes the lower leaf first
// (A's top cutter, leaf 1, before B's, leaf 4); regular leaves coincident
// half-spaces in ascending leaf order, and the tops are where the ray
// leaves the two top cutters, so A's cutter is left first there too
// (ref/fig04_ghost_regular.pov derives it).
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
    quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -RB*RB }
    plane { -y, -1 }
    plane { y, 0 }
    translate <0.6, 0, 0>
    pigment { color rgb <0.2, 0.75, 0.25> }
  }
  finish { ambient 0.15 diffuse 0.75 }
  rotate <9, 23, -7>
}
