// golden: skip radiosity scene: tests/test_cornell_truth.sh and bench/radiosity.sh compare it with its path-traced ground truth, not with POV-Ray
// Cornell box, measured geometry (Cornell University Program of Computer Graphics),
// lit only by an emitting ceiling patch; every surface is Lambertian.
// Used to compare radiosity / global illumination against a path-traced ground truth.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  radiosity {
    pretrace_start 0.04 pretrace_end 0.005
    count 1600 nearest_count 20 error_bound 0.2 recursion_limit 8
    low_error_factor 0.5 gray_threshold 0 minimum_reuse 0.005 brightness 1
    always_sample off
  }
}
#declare Light = <1.0, 0.67, 0.21> * 30;
#declare W = texture { pigment { rgb <0.75, 0.75, 0.75> } finish { diffuse 1 ambient 0 emission 0 } }
#declare R = texture { pigment { rgb <0.4275, 0.01875, 0.01875> } finish { diffuse 1 ambient 0 emission 0 } }
#declare G = texture { pigment { rgb <0.01875, 0.177, 0.01875> } finish { diffuse 1 ambient 0 emission 0 } }
camera {
  location  <27.8, 27.3, -80.0>
  direction <0, 0, 1>
  up        <0, 1, 0>
  right     <-1, 0, 0>
  angle 39.5
}
// light patch, facing down
union {
  triangle { <21.3, 54.87, 22.7>, <34.3, 54.87, 22.7>, <34.3, 54.87, 33.2> }
  triangle { <21.3, 54.87, 22.7>, <34.3, 54.87, 33.2>, <21.3, 54.87, 33.2> }
  texture { pigment { rgb 1 } finish { diffuse 0 ambient 0 emission Light } }
  no_shadow
}
union {
  triangle{<55.28, 0.0, 0.0>,<0.0, 0.0, 0.0>,<0.0, 0.0, 55.92>}
  triangle{<55.28, 0.0, 0.0>,<0.0, 0.0, 55.92>,<54.96, 0.0, 55.92>}
  triangle{<55.60, 54.88, 0.0>,<55.60, 54.88, 55.92>,<0.0, 54.88, 55.92>}
  triangle{<55.60, 54.88, 0.0>,<0.0, 54.88, 55.92>,<0.0, 54.88, 0.0>}
  triangle{<0.0, 54.88, 55.92>,<55.60, 54.88, 55.92>,<54.96, 0.0, 55.92>}
  triangle{<0.0, 54.88, 55.92>,<54.96, 0.0, 55.92>,<0.0, 0.0, 55.92>}
  texture { W }
}
union {
  triangle{<0.0, 54.88, 0.0>,<0.0, 54.88, 55.92>,<0.0, 0.0, 55.92>}
  triangle{<0.0, 54.88, 0.0>,<0.0, 0.0, 55.92>,<0.0, 0.0, 0.0>}
  texture { G }
}
union {
  triangle{<55.28, 0.0, 0.0>,<54.96, 0.0, 55.92>,<55.60, 54.88, 55.92>}
  triangle{<55.28, 0.0, 0.0>,<55.60, 54.88, 55.92>,<55.60, 54.88, 0.0>}
  texture { R }
}
union {
  triangle{<13.00, 16.50, 6.50>,<8.20, 16.50, 22.50>,<24.00, 16.50, 27.20>}
  triangle{<13.00, 16.50, 6.50>,<24.00, 16.50, 27.20>,<29.00, 16.50, 11.40>}
  triangle{<29.00, 0.0, 11.40>,<29.00, 16.50, 11.40>,<24.00, 16.50, 27.20>}
  triangle{<29.00, 0.0, 11.40>,<24.00, 16.50, 27.20>,<24.00, 0.0, 27.20>}
  triangle{<13.00, 0.0, 6.50>,<13.00, 16.50, 6.50>,<29.00, 16.50, 11.40>}
  triangle{<13.00, 0.0, 6.50>,<29.00, 16.50, 11.40>,<29.00, 0.0, 11.40>}
  triangle{<8.20, 0.0, 22.50>,<8.20, 16.50, 22.50>,<13.00, 16.50, 6.50>}
  triangle{<8.20, 0.0, 22.50>,<13.00, 16.50, 6.50>,<13.00, 0.0, 6.50>}
  triangle{<24.00, 0.0, 27.20>,<24.00, 16.50, 27.20>,<8.20, 16.50, 22.50>}
  triangle{<24.00, 0.0, 27.20>,<8.20, 16.50, 22.50>,<8.20, 0.0, 22.50>}
  texture { W }
}
union {
  triangle{<42.30, 33.00, 24.70>,<26.50, 33.00, 29.60>,<31.40, 33.00, 45.60>}
  triangle{<42.30, 33.00, 24.70>,<31.40, 33.00, 45.60>,<47.20, 33.00, 40.60>}
  triangle{<42.30, 0.0, 24.70>,<42.30, 33.00, 24.70>,<47.20, 33.00, 40.60>}
  triangle{<42.30, 0.0, 24.70>,<47.20, 33.00, 40.60>,<47.20, 0.0, 40.60>}
  triangle{<47.20, 0.0, 40.60>,<47.20, 33.00, 40.60>,<31.40, 33.00, 45.60>}
  triangle{<47.20, 0.0, 40.60>,<31.40, 33.00, 45.60>,<31.40, 0.0, 45.60>}
  triangle{<31.40, 0.0, 45.60>,<31.40, 33.00, 45.60>,<26.50, 33.00, 29.60>}
  triangle{<31.40, 0.0, 45.60>,<26.50, 33.00, 29.60>,<26.50, 0.0, 29.60>}
  triangle{<26.50, 0.0, 29.60>,<26.50, 33.00, 29.60>,<42.30, 33.00, 24.70>}
  triangle{<26.50, 0.0, 29.60>,<42.30, 33.00, 24.70>,<42.30, 0.0, 24.70>}
  texture { W }
}
