# gi_error.awk - the verdicts of bench/gi_error.sh, from one scene's table.
#
#   awk -v truth_spp=1024 -v name=cbox -f gi_error.awk NAME.tsv
#
# Rows: method, setting, cpu_seconds, rel_rmse.  Issue 11's targets for
# the outdoor sky scene and radiosity/cornell.pov, against POV-Ray's
# default settings (the "default" rung: radiosity { }, taking t_d
# seconds for an error e_d):
#   at t_d, zRcube's error is at most e_d: printed per method as the
#           lowest error of its rungs taking <= t_d, over e_d;
#   at e_d, zRcube takes at most half of t_d: printed per method as the
#           time of its fastest rung with error <= e_d, over t_d; and,
#           where the method's error/time curve crosses e_d between two
#           rungs, the time read off it there (log-log between the two
#           rungs of its lower envelope on either side of e_d: the
#           rungs no cheaper rung beats in error), over t_d.
# Also the truth's own noise (see bench/gi_error.sh), below which no
# error can be read.  Nothing is asserted; failed rungs are left out.
BEGIN { FS = "\t" }
NR == 1 { next }
function num(v) { return v != "" && v != "-" && v != "fail" }
num($3) && num($4) {
  n++
  m[n] = $1; s[n] = $2; t[n] = $3 + 0; e[n] = $4 + 0
  if ($1 == "povray" && $2 == "default") { td = $3 + 0; ed = $4 + 0 }
  if ($1 == "povray" && (best_p == 0 || $4 + 0 < e[best_p])) best_p = n
  if ($1 == "path" && $2 == "64") e64 = $4 + 0
}
END {
  if (e64 > 0) {
    r = 64 / truth_spp
    printf "  truth noise (from the 64-sample rung): %.4f\n", \
      e64 * sqrt(r / (1 + r))
  }
  # Issue 11's curved-surface target: relative error 0.10 in at most 5x
  # the time of POV-Ray's cheapest rung that reaches it.
  tp = -1
  for (i = 1; name == "curved" && i <= n; i++)
    if (m[i] == "povray" && e[i] <= 0.10 && (tp < 0 || t[i] < t[tp]))
      tp = i
  if (tp >= 0) {
    printf "  rel. error 0.10: POV-Ray's cheapest rung %s, %.2f s\n", \
      s[tp], t[tp]
    split("cache hier path", ms, " ")
    for (k = 1; k <= 3; k++) {
      fast = -1
      for (i = 1; i <= n; i++)
        if (m[i] == ms[k] && e[i] <= 0.10 && (fast < 0 || t[i] < t[fast]))
          fast = i
      if (fast >= 0)
        printf "    %-6s %s: %.2f s = %.3gx\n", ms[k] ":", s[fast], \
          t[fast], t[fast] / t[tp]
    }
  }
  if (!td) {
    print "  no POV-Ray default rung: no verdicts"
    exit 0
  }
  printf "  POV-Ray default: error %.4f in %.2f s; its best: %s, %.4f in" \
    " %.2f s\n", ed, td, s[best_p], e[best_p], t[best_p]
  split("cache hier path", ms, " ")
  for (k = 1; k <= 3; k++) {
    mm = ms[k]; at = -1; fast = -1; any = 0
    for (i = 1; i <= n; i++) {
      if (m[i] != mm) continue
      any = 1
      if (t[i] <= td && (at < 0 || e[i] < e[at])) at = i
      if (e[i] <= ed && (fast < 0 || t[i] < t[fast])) fast = i
    }
    if (!any) continue
    if (at < 0)
      line = "no rung within its time"
    else
      line = sprintf("at its time %s %s: error %.4f = %.2fx POV-Ray's", \
        mm, s[at], e[at], e[at] / ed)
    if (fast < 0)
      line = line "; no rung reaches its error"
    else
      line = line sprintf("; at its error %s %s: %.2f s = %.2fx its time", \
        mm, s[fast], t[fast], t[fast] / td)
    printf "  %-6s %s\n", mm ":", line
    # The lower envelope: the method's rungs by time, each kept when its
    # error is below every cheaper one's; then the pair around e_d.
    ne = 0
    for (i = 1; i <= n; i++) {
      if (m[i] != mm) continue
      beaten = 0
      for (j = 1; j <= n; j++)
        if (j != i && m[j] == mm && (t[j] < t[i] || (t[j] == t[i] && j < i)) \
            && e[j] <= e[i])
          beaten = 1
      if (!beaten) env[++ne] = i
    }
    for (i = 1; i <= ne; i++)  # by time (insertion sort)
      for (j = i; j > 1 && t[env[j]] < t[env[j - 1]]; j--) {
        x = env[j]; env[j] = env[j - 1]; env[j - 1] = x
      }
    for (i = 1; i < ne; i++) {
      a1 = env[i]; a2 = env[i + 1]
      if (e[a1] > ed && e[a2] <= ed && t[a1] > 0 && t[a2] > 0 && \
          e[a2] > 0) {
        f = (log(ed) - log(e[a1])) / (log(e[a2]) - log(e[a1]))
        ti = exp(log(t[a1]) + f * (log(t[a2]) - log(t[a1])))
        printf "  %-6s at its error, read between %s and %s (log-log):" \
          " %.3f s = %.2fx its time\n", "", s[a1], s[a2], ti, ti / td
      }
    }
  }
}
