// Fog seen from inside a solid or hollow plane, and a light with
// media_attenuation through the fog (tests/test_fog_povray.sh).
#version 3.6;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
camera { location <0, 20, -100> }
fog { color Gray50 distance 80 }
plane {z, 50 pigment { checker Yellow, Green scale 20 } finish { ambient 0.2 diffuse 0.8 } #ifdef (H) hollow #end }
light_source {<500, 600, -200>, color 40000*White #ifdef (MA) media_attenuation on #end }
