# summary.awk - the verdicts of bench/radiosity.sh, from its table.
#
#   awk -f summary.awk radiosity.tsv
#
# Rows: method, setting, seconds, rel_rmse, elements, links[, ...].
# Issue 4 sets two targets on one thread against POV-Ray's best rung (its
# lowest error e_p, taking t_p seconds):
#   speed:    zRcube reaches e_p in at most t_p / 10; printed as the
#             time of its fastest rung with error <= e_p over t_p;
#   accuracy: within t_p, zRcube's error is at most e_p / 2; printed as
#             the lowest error of its rungs taking <= t_p over e_p.
# And it asks how many fewer elements hierarchical radiosity needs than
# uniform subdivision for the same error: for each BF_eps rung, the
# fewest elements of a uniform rung with an error at most as low, over
# the rung's elements.  Nothing is asserted; rungs that failed ("fail")
# or lack a figure ("-") are left out.
BEGIN { FS = "\t" }
NR == 1 { next }
function num(v) { return v != "" && v != "-" && v != "fail" }
num($3) && num($4) {
  if ($1 == "povray" && (!pov_n || $4 < e_p)) {
    e_p = $4; t_p = $3; pov_set = $2
  }
  if ($1 == "povray") pov_n++
  if ($1 == "zr-bf" || $1 == "zr-unif") {
    zr_n++
    zr_m[zr_n] = $1; zr_s[zr_n] = $2; zr_t[zr_n] = $3; zr_e[zr_n] = $4
    zr_el[zr_n] = $5
  }
}
END {
  if (!pov_n) {
    print "no POV-Ray rung succeeded: no verdicts"
    exit 0
  }
  printf "POV-Ray's best: %s, rel_rmse %s in %s s\n", pov_set, e_p, t_p
  if (!zr_n) {
    print "no zRcube rung: no verdicts"
    exit 0
  }
  fast = -1; best = -1
  for (i = 1; i <= zr_n; i++) {
    if (zr_e[i] <= e_p && (fast < 0 || zr_t[i] < zr_t[fast])) fast = i
    if (zr_t[i] <= t_p && (best < 0 || zr_e[i] < zr_e[best])) best = i
  }
  if (fast < 0)
    print "speed: no zRcube rung reaches POV-Ray's best error (target:" \
      " within 1/10 of its time)"
  else
    printf "speed: zRcube %s %s reaches it in %s s, %.3f of POV-Ray's" \
      " time (target <= 0.1): %s\n", zr_m[fast], zr_s[fast], zr_t[fast],
      zr_t[fast] / t_p, zr_t[fast] / t_p <= 0.1 ? "met" : "NOT met"
  if (best < 0)
    print "accuracy: no zRcube rung finishes within POV-Ray's best time"
  else
    printf "accuracy: within that time zRcube %s %s has rel_rmse %s," \
      " %.3f of POV-Ray's (target <= 0.5): %s\n", zr_m[best], zr_s[best],
      zr_e[best], zr_e[best] / e_p,
      zr_e[best] / e_p <= 0.5 ? "met" : "NOT met"
  for (i = 1; i <= zr_n; i++) {
    if (zr_m[i] != "zr-bf" || !num(zr_el[i]) || zr_el[i] <= 0) continue
    u = -1
    for (j = 1; j <= zr_n; j++)
      if (zr_m[j] == "zr-unif" && num(zr_el[j]) && zr_e[j] <= zr_e[i] &&
          (u < 0 || zr_el[j] < zr_el[u])) u = j
    if (u < 0)
      printf "elements: BF_eps %s (rel_rmse %s, %d elements): no uniform" \
        " rung is as accurate\n", zr_s[i], zr_e[i], zr_el[i]
    else
      printf "elements: BF_eps %s (rel_rmse %s) uses %d elements, uniform" \
        " %s needs %d for rel_rmse %s: %.1f times fewer\n", zr_s[i],
        zr_e[i], zr_el[i], zr_s[u], zr_el[u], zr_e[u], zr_el[u] / zr_el[i]
  }
}
