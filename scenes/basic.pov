// basic.pov — a sphere with a cylindrical hole next to a box: the smallest
// scene that exercises union, difference and every primitive kind csgrt uses.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 40 right x*4/3 }
light_source { <-4, 6, -5> color rgb <1, 1, 1> }
background { color rgb <0.1, 0.1, 0.15> }

difference {
  sphere { <-1, 0.8, 0>, 0.9 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
  cylinder { <-1, 0.8, -2>, <-1, 0.8, 2>, 0.4 pigment { color rgb <0.2, 0.9, 0.3> } }
}
box { <0.3, 0, -0.6>, <1.5, 1.2, 0.6> rotate <0, 30, 0> pigment { color rgb <0.3, 0.5, 0.9> } }
cone { <2.2, 0, 0>, 0.5, <2.2, 1.3, 0>, 0.1 pigment { color rgb <0.9, 0.8, 0.2> } }
