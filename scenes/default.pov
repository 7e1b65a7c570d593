// default.pov — the scene `make sim` shows: what exact CSG is for.
//   - a die: a cube intersected with a sphere (rounded edges and corners)
//     minus 21 spherical pips,
//   - a washer: a cylinder minus a narrower, taller cylinder,
//   - a hollow ball with one octant cut away, showing the carved shell and
//     a pearl inside,
// all resting on a finite slab (no infinite plane: csgrt ends rays at a
// horizon that POV-Ray does not have). Objects sink slightly into the slab
// so that no two surfaces lie on each other.
//
// Mask comparison (model/povray_test.cpp): the background has red = 0 and
// every pigment has red > 0 with ambient > 0, so no object pixel can match
// the background colour exactly.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.3, 3.4, -6.8> look_at <0.05, 0.35, 0.2> angle 46 right x*4/3 up y }
light_source { <-5, 8, -6> color rgb <1, 1, 1> }
light_source { <6, 4, -3> color rgb <0.35, 0.35, 0.4> }
background { color rgb <0, 0.02, 0.06> }

// ---------------------------------------------------------------- the die
#declare PipR = 0.2;     // pip sphere radius
#declare PipO = 1.1;     // pip centre distance from the die centre (faces at 1)
#declare Die = difference {
  intersection {
    box { <-1, -1, -1>, <1, 1, 1> }
    sphere { <0, 0, 0>, 1.36 }
  }
  // +y: five
  sphere { <0, PipO, 0>, PipR }
  sphere { <-0.5, PipO, -0.5>, PipR }
  sphere { < 0.5, PipO, -0.5>, PipR }
  sphere { <-0.5, PipO,  0.5>, PipR }
  sphere { < 0.5, PipO,  0.5>, PipR }
  // -y: two
  sphere { <-0.5, -PipO, -0.5>, PipR }
  sphere { < 0.5, -PipO,  0.5>, PipR }
  // -z: three
  sphere { <-0.5,  0.5, -PipO>, PipR }
  sphere { < 0,    0,   -PipO>, PipR }
  sphere { < 0.5, -0.5, -PipO>, PipR }
  // +z: four
  sphere { <-0.5, -0.5, PipO>, PipR }
  sphere { < 0.5, -0.5, PipO>, PipR }
  sphere { <-0.5,  0.5, PipO>, PipR }
  sphere { < 0.5,  0.5, PipO>, PipR }
  // -x: one
  sphere { <-PipO, 0, 0>, PipR }
  // +x: six
  sphere { <PipO, -0.5, -0.5>, PipR }
  sphere { <PipO,  0,   -0.5>, PipR }
  sphere { <PipO,  0.5, -0.5>, PipR }
  sphere { <PipO, -0.5,  0.5>, PipR }
  sphere { <PipO,  0,    0.5>, PipR }
  sphere { <PipO,  0.5,  0.5>, PipR }
  pigment { color rgb <0.92, 0.9, 0.82> }
  finish { ambient 0.15 diffuse 0.75 phong 0.5 phong_size 60 }
}

object { Die scale 0.62 rotate <0, -28, 0> translate <0.1, 0.59, 0.35> }

// ------------------------------------------------------------- the washer
difference {
  cylinder { <0, -0.05, 0>, <0, 0.22, 0>, 0.62 }
  cylinder { <0, -0.2, 0>, <0, 0.4, 0>, 0.3 }
  pigment { color rgb <0.85, 0.6, 0.2> }
  finish { ambient 0.12 diffuse 0.7 phong 0.8 phong_size 80 reflection 0.1 }
  translate <-1.85, 0, -0.2>
}

// ------------------------------------ the hollow ball with an octant cut away
union {
  difference {
    sphere { <0, 0, 0>, 0.7 }
    sphere { <0, 0, 0>, 0.5 }
    box { <-1, 0, -1>, <0, 1, 0> }
    pigment { color rgb <0.25, 0.45, 0.85> }
    finish { ambient 0.12 diffuse 0.75 phong 0.6 phong_size 50 }
  }
  sphere { <0, 0, 0>, 0.3
    pigment { color rgb <0.9, 0.2, 0.25> }
    finish { ambient 0.12 diffuse 0.7 phong 0.9 phong_size 120 }
  }
  rotate <0, -35, 0>
  translate <1.95, 0.66, 0.1>
}

// --------------------------------------------------------------- the slab
box { <-3.2, -0.4, -1.6>, <3.2, 0, 2.2>
  pigment { color rgb <0.55, 0.57, 0.6> }
  finish { ambient 0.1 diffuse 0.7 }
}
