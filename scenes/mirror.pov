// mirror.pov — a mirror ball and a mirror wall on a CSG floor: shadows and
// reflections traced from rounded hit points with no offset at all.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0.4, 2.2, -5.5> look_at <0, 0.7, 0> angle 42 right x*4/3 }
light_source { <-3, 5, -4> color rgb <1, 1, 1> }
light_source { <4, 4, -2> color rgb <0.35, 0.35, 0.4> }
background { color rgb <0.05, 0.07, 0.12> }

// floor: a slab with a shallow square recess
difference {
  box { <-3, -0.3, -2.5>, <3, 0, 3> }
  box { <-1.2, -0.1, -1.2>, <1.2, 0.01, 1.2> }
  pigment { color rgb <0.55, 0.55, 0.6> } finish { diffuse 0.8 }
}
// mirror ball resting in the recess
sphere { <0, 0.7, 0>, 0.8 pigment { color rgb <0.9, 0.9, 0.95> }
         finish { ambient 0.05 diffuse 0.2 reflection 0.7 phong 0.8 phong_size 60 } }
// a mirror wall behind, tilted
box { <-2.5, 0, 2.2>, <2.5, 2.2, 2.35> rotate <0, -12, 0>
      pigment { color rgb <0.8, 0.85, 0.9> } finish { ambient 0.02 diffuse 0.1 reflection 0.8 } }
// coloured props that the mirrors show
cylinder { <-1.9, 0, -0.6>, <-1.9, 1.2, -0.6>, 0.3 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.4 } }
cone { <1.8, 0, -0.8>, 0.45, <1.8, 1.3, -0.8>, 0.05 pigment { color rgb <0.2, 0.7, 0.3> } finish { phong 0.4 } }
