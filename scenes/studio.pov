// studio.pov — machined parts under three shadowless studio lights (a key,
// a cool fill and a rim light, POV-Ray's `shadowless`): a product shot with
// no cast shadows, so the scene uses no effect unit and `make sim` builds
// the tracer without the ray tree (docs/effects.md, "Shadowless lights").
//   - two hex nuts: six planes and two caps, the corners rounded by a
//     sphere (the chamfer), minus the bore,
//   - a hex-head bolt lying on its side,
//   - a washer and a ball bearing,
// on a finite slab. Objects sink slightly into the slab so that no two
// surfaces lie on each other.
//
// Mask comparison (model/povray_test.cpp): the background has red = 0 and
// every pigment has red > 0 with ambient > 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.4, 3.9, -6.4> look_at <0.1, 0.3, 0.2> angle 40 right x*4/3 up y }
light_source { <-5, 8, -6> color rgb <1, 0.95, 0.85> shadowless }   // key
light_source { <6, 3, -5> color rgb <0.3, 0.35, 0.45> shadowless }  // fill
light_source { <1, 5, 9> color rgb <0.55, 0.55, 0.6> shadowless }   // rim
background { color rgb <0, 0.025, 0.05> }

// A hexagonal prism across flats 2*0.5, height 0.4 (y from 0 to 0.4),
// corners rounded by a sphere.
#declare Hex = intersection {
  plane { < 1, 0, 0>, 0.5 }
  plane { <-1, 0, 0>, 0.5 }
  plane { < 0.5, 0,  0.8660254>, 0.5 }
  plane { <-0.5, 0, -0.8660254>, 0.5 }
  plane { <-0.5, 0,  0.8660254>, 0.5 }
  plane { < 0.5, 0, -0.8660254>, 0.5 }
  plane { y, 0.4 }
  plane { -y, 0 }
  sphere { <0, 0.2, 0>, 0.6 }
}

// ------------------------------------------------------------ the nuts
difference {
  object { Hex }
  cylinder { <0, -0.1, 0>, <0, 0.5, 0>, 0.27 }
  pigment { color rgb <0.75, 0.72, 0.66> }
  finish { ambient 0.12 diffuse 0.65 phong 0.7 phong_size 60 }
  rotate <0, 12, 0>
  translate <-1.6, -0.02, 0.6>
}
difference {
  object { Hex }
  cylinder { <0, -0.1, 0>, <0, 0.5, 0>, 0.27 }
  pigment { color rgb <0.85, 0.62, 0.3> }
  finish { ambient 0.12 diffuse 0.65 phong 0.8 phong_size 80 }
  scale 0.8
  rotate <0, -20, 0>
  translate <-0.5, -0.02, -0.9>
}

// ---------------------------------------------------- the bolt, on its side
union {
  object { Hex scale <1, 0.8, 1> }
  cylinder { <0, 0.3, 0>, <0, 2.0, 0>, 0.26 }
  pigment { color rgb <0.6, 0.63, 0.7> }
  finish { ambient 0.12 diffuse 0.65 phong 0.6 phong_size 50 }
  rotate <0, 0, -90>          // the shaft along +x
  rotate <0, 30, 0>
  translate <0.4, 0.48, 0.9>
}

// ------------------------------------------------ the washer and the ball
difference {
  cylinder { <0, -0.02, 0>, <0, 0.1, 0>, 0.55 }
  cylinder { <0, -0.1, 0>, <0, 0.2, 0>, 0.3 }
  pigment { color rgb <0.7, 0.7, 0.72> }
  finish { ambient 0.12 diffuse 0.65 phong 0.5 }
  translate <1.3, 0, -0.9>
}
sphere { <-1.8, 0.32, -0.7>, 0.35
  pigment { color rgb <0.9, 0.25, 0.2> }
  finish { ambient 0.12 diffuse 0.65 phong 0.9 phong_size 120 }
}

// ------------------------------------------------------------- the slab
box { <-3.4, -0.4, -2.2>, <3.6, 0, 3.0>
  pigment { color rgb <0.32, 0.34, 0.38> }
  finish { ambient 0.1 diffuse 0.7 }
}
