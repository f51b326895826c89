// tests/media_shell.pov - media in a CSG shell and media lit by a shadowless
// light (tests/test_media_shell.sh).  Case selects the scene:
//   1 a shell of absorbing media (difference of two spheres, density
//     { rgb 1 }) moved by a translate after its interior, seen from
//     outside: the rays through the middle cross the hole, where there
//     is no medium;
//   2 the same shell of scattering media;
//   3 the camera in the hole of the scattering shell (the clouds of
//     advanced/benchmark/benchmark.pov) inside a sky sphere: the rays
//     leave the shell into the open, where there is no medium either;
//   4 a box of scattering media lit by a shadowless light;
//   5 atmospheric scattering media lit by a shadowless light;
//   6 case 4's box with a light that casts shadows;
//   7 the camera in the hole of a shell scaled <1, 1, 0.4> of absorbing
//     and scattering media: the first sample of a ray, on the inner
//     surface, whose shadow ray goes back into the hole (the picture's
//     left side), counts the hole as medium and the shell behind as
//     clear.
#version 3.7;
#ifndef (Case) #declare Case = 1; #end
global_settings { assumed_gamma 1 }
background { rgb <0.2, 0.3, 0.6> }
#if (Case = 7)
  camera { location 0 look_at <-1, 1, 0> angle 90 }
  light_source { <-10, 12, 3> color rgb 1 }
  background { rgb 0.1 }
  difference {
    sphere { 0, 5 }
    sphere { 0, 3.5 }
    pigment { rgbf 1 }
    finish { ambient 0 diffuse 0 }
    interior {
      media {
        scattering { 1, 1 extinction 0 }
        absorption 1
        method 3 samples 7, 7 intervals 1 aa_level 1
      }
    }
    hollow
    scale <1, 1, 0.4>
  }
#elseif (Case <= 3)
  #if (Case = 3)
    camera { location <0, 0, 0.5> look_at <0, 1, 0.9> angle 60 }
    sphere { 0, 10 pigment { rgb <0.2, 0.3, 0.6> }
      finish { ambient 1 diffuse 0 } hollow }
  #else
    camera { location <0, -5, 0.5> look_at <0, 0, 0.5> angle 40 }
  #end
  light_source { <10, 0, 8> color rgb <3.43, 2.87, 1.95> }
  difference {
    sphere { 0, 1 }
    sphere { 0, 0.8 }
    pigment { rgbf 1 }
    finish { ambient 0 diffuse 0 }
    interior {
      media {
        #if (Case = 1)
          absorption 1
        #else
          scattering { 1, 0.3 extinction 1 }
        #end
        method 3 samples 7, 7 intervals 1
        density { rgb 1 }
      }
    }
    hollow
    translate z * 0.5
  }
#else
  camera { location <0, -5, 0.5> look_at <0, 0, 0.5> angle 40 }
  light_source { <10, 0, 8> color rgb 1 #if (Case != 6) shadowless #end }
  #if (Case = 5)
    plane { y, 5 pigment { rgb 0.5 } hollow }
    media { scattering { 1, 0.05 } }
  #else
    box { <-1, -1, 0>, <1, 1, 1>
      pigment { rgbf 1 }
      finish { ambient 0 diffuse 0 }
      interior {
        media {
          scattering { 1, 0.3 extinction 1 }
          method 3 samples 7, 7 intervals 1
          density { rgb 3 }
        }
      }
      hollow
    }
  #end
#end
