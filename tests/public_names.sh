#!/bin/sh
# public_names.sh HEADER - the functions HEADER exports (its ZR_API
# declarations), one name a line, sorted.  Shared by test_symbols.sh and
# test_manpages.sh.
awk '
  /^ZR_API/ { decl = ""; inside = 1 }
  inside { decl = decl " " $0 }
  inside && /;/ {
    inside = 0
    sub(/\(.*/, "", decl)          # up to the parameter list
    n = split(decl, w, /[ *]+/)
    print w[n]
  }' "$1" | LC_ALL=C sort -u
