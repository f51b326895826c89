#declare F = function { internal(61) }
#declare G = function { F(x,y,z,1) + F(y,z,x,2) }
#declare V = G(1,2,3);
#declare W = F(1);
