# with_block.awk - a scene with its radiosity block replaced by the
# contents of the file named by -v block=FILE (an empty file removes
# it).  Braces are counted, so the block may span lines.  Used by
# bench/radiosity.sh and bench/gi_error.sh:
#   awk -v block=FILE -f with_block.awk scene.pov > copy.pov
skip == 0 && /radiosity[ \t]*\{/ {
  i = index($0, "radiosity")
  printf "%s", substr($0, 1, i - 1)
  while ((getline l < block) > 0) print l
  rest = substr($0, i)
  skip = 1; depth = 0
  for (k = 1; k <= length(rest); k++) {
    c = substr(rest, k, 1)
    if (c == "{") depth++
    if (c == "}" && --depth == 0) {
      print substr(rest, k + 1); skip = 0; break
    }
  }
  next
}
skip == 1 {
  for (k = 1; k <= length($0); k++) {
    c = substr($0, k, 1)
    if (c == "{") depth++
    if (c == "}" && --depth == 0) {
      print substr($0, k + 1); skip = 0; break
    }
  }
  next
}
{ print }
