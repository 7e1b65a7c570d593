// rotated.pov — everything off-axis: no face, axis or cut lies along a
// coordinate axis, so every quadric has cross terms.
//   - a hex nut: three boxes rotated 0/60/120 degrees, intersected, minus a
//     cylinder, tipped over,
//   - a tumbling cube drilled through,
//   - a tube (cylinder minus cylinder) leaning across the platform,
//   - a cone lying on its side, an ellipsoid and a ball with a rotated
//     wedge cut out,
// on a tilted, turned slab. Objects sink slightly into the slab so that no
// two surfaces lie on each other.
//
// Mask comparison (model/povray_test.cpp): the background has red = 0 and
// every pigment has red > 0 with ambient > 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <-0.3, 4.6, -8.0> look_at <0.25, 0.45, 0.3> angle 44 right x*4/3 up y }
light_source { <-6, 8, -6> color rgb <1, 1, 1> }
light_source { <7, 5, -3> color rgb <0.3, 0.32, 0.4> }
background { color rgb <0, 0.035, 0.05> }

union {
  // ---------------------------------------------------------- hex nut
  difference {
    intersection {
      // different heights, so that the boxes' top and bottom faces do not
      // lie on each other: the nut's faces are the first box's
      box { <-0.6, -0.22, -1>, <0.6, 0.22, 1> }
      box { <-0.6, -0.26, -1>, <0.6, 0.26, 1> rotate <0, 60, 0> }
      box { <-0.6, -0.3, -1>, <0.6, 0.3, 1> rotate <0, 120, 0> }
    }
    cylinder { <0, -0.5, 0>, <0, 0.5, 0>, 0.32 }
    pigment { color rgb <0.75, 0.72, 0.6> }
    finish { ambient 0.12 diffuse 0.7 phong 0.8 phong_size 80 reflection 0.1 }
    rotate <62, 18, 0>
    translate <-1.9, 0.55, 0.2>
  }

  // ----------------------------------------------- cube drilled through
  difference {
    box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> }
    cylinder { <0, 0, -1>, <0, 0, 1>, 0.22 }
    pigment { color rgb <0.3, 0.5, 0.9> }
    finish { ambient 0.12 diffuse 0.75 phong 0.5 }
    rotate <-28, 22, 12>
    translate <0.2, 0.55, 1.15>
  }

  // ------------------------------------------------------------- tube
  difference {
    cylinder { <0, 0, -1.1>, <0, 0, 1.1>, 0.28 }
    cylinder { <0, 0, -1.3>, <0, 0, 1.3>, 0.2 }
    pigment { color rgb <0.9, 0.55, 0.2> }
    finish { ambient 0.12 diffuse 0.7 phong 0.7 phong_size 60 }
    rotate <-14, 38, 0>
    translate <1.85, 0.45, 1.0>
  }

  // ---------------------------------------------------- cone on its side
  cone { <0, -0.6, 0>, 0.32, <0, 0.6, 0>, 0.05
    pigment { color rgb <0.35, 0.8, 0.5> }
    finish { ambient 0.12 diffuse 0.7 phong 0.5 }
    rotate <0, 0, 75>
    rotate <0, -35, 0>
    translate <1.75, 0.3, -1.05>
  }

  // --------------------------------------------------------- ellipsoid
  sphere { <0, 0, 0>, 1
    scale <0.5, 0.22, 0.3>
    rotate <20, 40, -25>
    translate <-0.6, 0.25, -1.1>
    pigment { color rgb <0.8, 0.35, 0.7> }
    finish { ambient 0.12 diffuse 0.7 phong 0.8 phong_size 90 }
  }

  // ------------------------------------------- ball with a wedge cut out
  difference {
    sphere { <0, 0, 0>, 0.5 }
    box { <-0.7, -0.7, -0.7>, <0, 0.7, 0> rotate <8, -58, 5> }
    pigment { color rgb <0.9, 0.3, 0.3> }
    finish { ambient 0.12 diffuse 0.7 phong 0.6 phong_size 50 }
    translate <0.35, 0.47, -1.0>
  }

  // ------------------------------------------------------------- slab
  box { <-3.0, -0.35, -1.9>, <3.0, 0, 2.3>
    pigment { color rgb <0.5, 0.52, 0.56> }
    finish { ambient 0.1 diffuse 0.7 }
  }
  rotate <5, 14, -4>
}
