// lantern.pov — a lamp inside a pierced box on a floor: its light leaves
// only through the four holes and throws four spots on the floor, while a
// dim fill light from outside shows the box. A shadow ray from the floor to
// the lamp crosses the box's near wall before the light and its far wall
// past it, so the ray's t limit keeps one event of a leaf and drops the
// other (the event sorter's input stage, tb/frame's LightInsideAnObject).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <1.6, 3.2, -4.2> look_at <0, 0.4, 0> angle 44 right x*4/3 }
light_source { <0, 0.62, 0> color rgb <1, 0.85, 0.55> }          // the lamp, inside the box
light_source { <-4, 5, -3> color rgb <0.25, 0.27, 0.32> }        // fill, outside
background { color rgb <0.03, 0.03, 0.06> }

box { <-4, -0.2, -3>, <4, 0, 5> pigment { color rgb <0.75, 0.72, 0.68> } finish { diffuse 0.9 } }
difference {
  box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> }
  box { <-0.5, 0.1, -0.5>, <0.5, 1.1, 0.5> }
  cylinder { <-1, 0.55, 0>, <1, 0.55, 0>, 0.22 }
  cylinder { <0, 0.55, -1>, <0, 0.55, 1>, 0.22 }
  pigment { color rgb <0.8, 0.25, 0.15> } finish { diffuse 0.8 phong 0.3 }
}
