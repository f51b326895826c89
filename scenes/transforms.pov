// transforms.pov - scale, rotate, translate and matrix.
//
// Each transformation applies to what came before it, in order (POV-Ray
// reference, "Transformations"): the same box is scaled then rotated
// then moved, and moved then rotated, which puts it elsewhere; a matrix
// shears a box; a union is transformed as a whole after its parts.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> look_at <0, 1, 0> angle 55 }
light_source { <-6, 10, -8>, rgb 1 }
background { rgb <0.55, 0.65, 0.8> }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }

#declare Unit = box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> }

// Scale, rotate, translate.
object { Unit pigment { rgb <0.9, 0.2, 0.2> }
         scale <2, 1, 0.5> rotate y * 30 translate <-3, 0.5, 0> }
// Translate then rotate: swings around the origin.
object { Unit pigment { rgb <0.2, 0.8, 0.2> }
         translate <3, 0.5, 0> rotate y * -40 }
// A shear: x grows with y.
object { Unit pigment { rgb <0.2, 0.3, 0.9> }
         matrix < 1, 0, 0,
                  0.6, 1, 0,
                  0, 0, 1,
                  -0.9, 0.5, 2.2 > }
// Rotation about all three axes and a uniform scale.
cylinder { <-0.5, 0, 0>, <0.5, 0, 0>, 0.3 pigment { rgb <0.9, 0.8, 0.1> }
           rotate <20, 45, 60> scale 1.5 translate <0.6, 1.5, -1.8> }
// A union moved as one.
union {
  sphere { <-0.6, 0, 0>, 0.4 }
  sphere { <0.6, 0, 0>, 0.4 }
  cylinder { <-0.6, 0, 0>, <0.6, 0, 0>, 0.15 }
  pigment { rgb <0.8, 0.3, 0.8> }
  rotate z * 30
  translate <2.5, 2.5, 2>
}
