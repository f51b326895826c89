#!/bin/sh
# test_manpages.sh - every public function of include/zrcube.h is named
# in the NAME section of a section-3 page of man/ (one page per family of
# functions; libzrcube(3) is the index), and every page is installed
# (listed in man/local.mk).
set -u
: "${ZR_SRCDIR:?}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
man="$ZR_SRCDIR/man"
# The names each family page's NAME section lists.
for page in "$man"/zr_*.3; do
  sed -n '/^\.SH NAME/,/^\.SH/p' "$page" | sed '1d;$d' | tr '\n' ' ' |
    sed 's/\\-.*//' | tr ',' '\n' | tr -d ' ' | grep -v '^$'
done | LC_ALL=C sort -u > "$tmp/named"
sh "$ZR_SRCDIR/tests/public_names.sh" "$ZR_SRCDIR/include/zrcube.h" \
  > "$tmp/public"
failed=0
missing=$(LC_ALL=C comm -23 "$tmp/public" "$tmp/named")
if [ -n "$missing" ]; then
  echo "test_manpages: public functions no page names (add each to the" \
       "NAME and SYNOPSIS of its family's page in man/):" >&2
  echo "$missing" | sed 's/^/  /' >&2
  failed=1
fi
extra=$(LC_ALL=C comm -13 "$tmp/public" "$tmp/named")
if [ -n "$extra" ]; then
  echo "test_manpages: pages name functions zrcube.h does not declare:" >&2
  echo "$extra" | sed 's/^/  /' >&2
  failed=1
fi
for page in "$man"/*.3; do
  name=$(basename "$page")
  grep -q "man/$name" "$man/local.mk" "$ZR_SRCDIR/Makefile.am" || {
    echo "test_manpages: man/$name is not installed (man/local.mk)" >&2
    failed=1
  }
done
[ "$failed" = 0 ] || exit 1
echo "test_manpages: $(wc -l < "$tmp/public") functions, each named in a" \
     "page of $(ls "$man"/zr_*.3 | wc -l) families"
