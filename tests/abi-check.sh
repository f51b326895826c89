#!/bin/sh
# abi-check.sh - `make abi-check`: compares the ABI of the libzrcube just
# built with the one of the previous release tag (abidiff, Debian package
# abigail-tools), both with their public header only (zrcube.h), so only
# what a program can see counts.
#
#   ABI_BASE=v0.1.0 make abi-check     (default: the newest v* tag)
#
# It builds the tag's library in a temporary folder (git archive,
# autoreconf, configure, make lib/libzrcube.la), prints abidiff's report,
# and fails when the change is incompatible (abidiff's bit 8: a type
# changed size or layout, a function went) but libtool's current number
# (-version-info current:revision:age in Makefile.am) was not raised, or
# when it is compatible but current was raised without age: libtool's
# rules (libtool manual, "Updating version info").
set -u
: "${ZR_SRCDIR:?}" "${ZR_BUILDDIR:?}"
command -v abidiff > /dev/null || {
  echo "abi-check: abidiff is missing (Debian: apt-get install" \
       "abigail-tools)" >&2
  exit 2
}
base=${ABI_BASE:-$(git -C "$ZR_SRCDIR" describe --tags --abbrev=0 \
                     --match 'v[0-9]*' 2> /dev/null)}
[ -n "$base" ] || { echo "abi-check: no v* release tag to compare with" >&2;
                    exit 2; }
new="$ZR_BUILDDIR/lib/.libs/libzrcube.so"
[ -e "$new" ] || { echo "abi-check: no shared library at $new" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "abi-check: building libzrcube of $base in $tmp"
mkdir "$tmp/src"
git -C "$ZR_SRCDIR" archive "$base" | tar -x -C "$tmp/src" || exit 2
( cd "$tmp/src" && autoreconf -fi > "$tmp/log" 2>&1 && mkdir b && cd b &&
  ../configure --disable-static CFLAGS='-g -O2' >> "$tmp/log" 2>&1 &&
  make -j2 lib/libzrcube.la >> "$tmp/log" 2>&1 ) ||
  { tail -20 "$tmp/log" >&2; echo "abi-check: cannot build $base" >&2;
    exit 2; }
old="$tmp/src/b/lib/.libs/libzrcube.so"
info() { sed -n 's/.*-version-info \([0-9:]*\).*/\1/p' "$1" | head -1; }
was=$(info "$tmp/src/Makefile.am")
now=$(info "$ZR_SRCDIR/Makefile.am")
echo "abi-check: $base (version-info $was) against this tree ($now)"
abidiff --headers-dir1 "$tmp/src/include" --headers-dir2 "$ZR_SRCDIR/include" \
  "$old" "$new"
rc=$?
cur_was=${was%%:*}
cur_now=${now%%:*}
age_was=${was##*:}
age_now=${now##*:}
if [ $((rc & 1)) -ne 0 ]; then
  echo "abi-check: abidiff failed ($rc)" >&2
  exit 2
elif [ $((rc & 8)) -ne 0 ]; then
  if [ "$cur_now" -le "$cur_was" ] || [ "$age_now" -ne 0 ]; then
    echo "abi-check: incompatible change: raise current and set age to 0" \
         "in -version-info (now $now)" >&2
    exit 1
  fi
  echo "abi-check: incompatible change, and -version-info $now says so"
elif [ $((rc & 4)) -ne 0 ]; then
  if [ "$cur_now" -le "$cur_was" ]; then
    echo "abi-check: compatible additions: raise current and age in" \
         "-version-info (now $now)" >&2
    exit 1
  fi
  echo "abi-check: compatible change, -version-info $now"
else
  echo "abi-check: same ABI as $base"
fi
