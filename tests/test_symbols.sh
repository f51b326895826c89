#!/bin/sh
# test_symbols.sh - the library's exported symbols are the list in
# lib/libzrcube.sym, and so are the ZR_API declarations of
# include/zrcube.h: nothing internal leaks (zr__ functions, helpers of
# the codecs), and nothing public is missing or undeclared.
set -u
: "${ZR_SRCDIR:?}" "${ZR_BUILDDIR:?}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
grep -v '^#' "$ZR_SRCDIR/lib/libzrcube.sym" | LC_ALL=C sort -u > "$tmp/list"
sh "$ZR_SRCDIR/tests/public_names.sh" "$ZR_SRCDIR/include/zrcube.h" \
  > "$tmp/header"
if ! diff "$tmp/list" "$tmp/header" > "$tmp/d1"; then
  echo "test_symbols: lib/libzrcube.sym (<) and zrcube.h's ZR_API" \
       "declarations (>) differ:" >&2
  cat "$tmp/d1" >&2
  failed=1
fi
so="$ZR_BUILDDIR/lib/.libs/libzrcube.so"
if [ -e "$so" ]; then
  nm -D --defined-only "$so" | awk '$2 ~ /^[TDBRVWi]$/ { print $3 }' |
    LC_ALL=C sort -u > "$tmp/exported"
  if ! diff "$tmp/list" "$tmp/exported" > "$tmp/d2"; then
    echo "test_symbols: lib/libzrcube.sym (<) and the symbols" \
         "libzrcube.so exports (>) differ:" >&2
    cat "$tmp/d2" >&2
    failed=1
  fi
  # The library never ends the process: no exit() (flex's default fatal
  # error handler called it; grammar/pov.l routes it to a status).
  if nm -D --undefined-only "$so" | awk '{ print $2 }' |
       grep -E '^(exit|_exit|_Exit|quick_exit)(@|$)'; then
    echo "test_symbols: libzrcube.so calls the function above" >&2
    failed=1
  fi
  checked="the header and libzrcube.so"
else
  checked="the header (no shared library in this build)"
fi
[ "$failed" = 0 ] || exit 1
echo "test_symbols: $(wc -l < "$tmp/list") symbols, as $checked say"
