// Fig. 15: a spherical lamina with a reflective backplane. A sphere minus
// itself (exactly coincident surfaces everywhere), its top cut off by a
// plane. Under ties "paper" the positive sphere is always struck first, so
// the lamina is visible from outside only: looking in through the cut, the
// inside of the far wall is invisible (rays pass to the backplane), though
// the far wall shows in the mirror once reflection exists. Under "regular"
// a sphere minus itself is empty: nothing is there.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.6, -4.6> look_at <0, 0.2, 0> angle 44 right x*4/3 up y }
light_source { <-5, 9, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -5> color rgb <0.3, 0.3, 0.3> }
background { color rgb <0.08, 0.12, 0.45> }
difference {
  sphere { <0, 0, 0>, 1 }
  sphere { <0, 0, 0>, 1 }
  plane { -y, -0.35 }
  pigment { color rgb <0.95, 0.75, 0.25> }
  finish { ambient 0.15 diffuse 0.75 phong 0.4 }
  rotate <-12, 15, 6>
}
box { <-3.5, -1.2, 1.6>, <3.5, 3, 1.8>
  pigment { color rgb <0.55, 0.6, 0.7> }
  finish { ambient 0.1 diffuse 0.5 reflection 0.6 }
  rotate <0, 8, 0>
}
box { <-3.5, -1.4, -3>, <3.5, -1.2, 1.6> pigment { color rgb <0.45, 0.4, 0.35> } }
