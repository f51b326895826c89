/*
 * strbuf.c - growable strings for messages and file contents.
 */
#include "core/strbuf.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void zr__strbuf_init(zr_strbuf *sb) { memset(sb, 0, sizeof *sb); }

void zr__strbuf_free(zr_strbuf *sb) {
  free(sb->data);
  zr__strbuf_init(sb);
}

static bool reserve(zr_strbuf *sb, size_t extra) {
  if (sb->failed)
    return false;
  if (sb->len + extra + 1 <= sb->cap)
    return true;
  size_t cap = sb->cap ? sb->cap : 64;
  while (cap < sb->len + extra + 1)
    cap *= 2;
  char *data = realloc(sb->data, cap);
  if (!data) {
    sb->failed = true;
    return false;
  }
  sb->data = data;
  sb->cap = cap;
  return true;
}

void zr__strbuf_append(zr_strbuf *sb, const char *s, size_t n) {
  if (!reserve(sb, n))
    return;
  memcpy(sb->data + sb->len, s, n);
  sb->len += n;
  sb->data[sb->len] = '\0';
}

void zr__strbuf_puts(zr_strbuf *sb, const char *s) {
  zr__strbuf_append(sb, s, strlen(s));
}

void zr__strbuf_putc(zr_strbuf *sb, char c) { zr__strbuf_append(sb, &c, 1); }

void zr__strbuf_vprintf(zr_strbuf *sb, const char *fmt, va_list ap) {
  va_list copy;
  va_copy(copy, ap);
  int n = vsnprintf(NULL, 0, fmt, copy);
  va_end(copy);
  if (n < 0 || !reserve(sb, (size_t)n))
    return;
  vsnprintf(sb->data + sb->len, (size_t)n + 1, fmt, ap);
  sb->len += (size_t)n;
}

void zr__strbuf_printf(zr_strbuf *sb, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  zr__strbuf_vprintf(sb, fmt, ap);
  va_end(ap);
}

const char *zr__strbuf_cstr(const zr_strbuf *sb) {
  return (sb->data && !sb->failed) ? sb->data : "";
}

char *zr__strbuf_take(zr_strbuf *sb) {
  char *s = sb->failed ? NULL : sb->data;
  if (!s && !sb->failed)
    s = calloc(1, 1);
  if (sb->failed)
    free(sb->data);
  zr__strbuf_init(sb);
  return s;
}
