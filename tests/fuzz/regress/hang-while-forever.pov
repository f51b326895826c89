// A #while whose condition never changes: POV-Ray 3.7 loops forever too.
// libFuzzer reports it as a timeout; the engine has no iteration limit.
#declare I = 0;
#while (I < 1)
#end
