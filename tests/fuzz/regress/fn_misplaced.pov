function { x }
sphere { 0, 1 }
#declare F = function(x, y, x) { 1 }
