// layer_tir.pov: a clear glass block under a two-layer texture, a clear
// lower layer (pigment rgbf 0.9) beneath a fresnel-reflecting glass
// layer (advanced/glasschess.pov's pieces).  Inside the block most rays
// are totally reflected (tests/test_layer_tir.sh).
global_settings { max_trace_level 15 }
camera { location <0, 0.6, -4> look_at 0 angle 40 }
light_source { <5, 5, -5> rgb 1 }
plane { y, -1.2 pigment { checker rgb 1 rgb <0.2, 0.4, 0.8> } }
background { rgb <0.2, 0.3, 0.5> }
#declare Glass = texture {
  pigment { rgbf <0.98, 1.0, 0.98, 1> }
  finish { specular 1 roughness 0.001 ambient 0 diffuse 0
           reflection { 0, 1 fresnel } }
}
superellipsoid { <0.05, 0.05> scale <0.8, 1, 0.8> rotate y*30
  pigment { rgbf 0.9 }
  texture { Glass }
  interior { ior 1.5 fade_distance 2 fade_power 2 }
}
