/*
 * strbuf.h - a growable byte string, always NUL-terminated.  An allocation
 * failure sets 'failed' and turns later appends into no-ops, so callers
 * check once at the end.
 */
#ifndef ZR_CORE_STRBUF_H
#define ZR_CORE_STRBUF_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>

typedef struct zr_strbuf {
  char *data;
  size_t len;
  size_t cap;
  bool failed;
} zr_strbuf;

void zr__strbuf_init(zr_strbuf *sb);
void zr__strbuf_free(zr_strbuf *sb);
void zr__strbuf_append(zr_strbuf *sb, const char *s, size_t n);
void zr__strbuf_puts(zr_strbuf *sb, const char *s);
void zr__strbuf_putc(zr_strbuf *sb, char c);
void zr__strbuf_printf(zr_strbuf *sb, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
void zr__strbuf_vprintf(zr_strbuf *sb, const char *fmt, va_list ap);
/* The text so far; "" for an empty or failed buffer. */
const char *zr__strbuf_cstr(const zr_strbuf *sb);
/* Hands the malloc'ed text to the caller (NULL if failed) and resets sb. */
char *zr__strbuf_take(zr_strbuf *sb);

#endif /* ZR_CORE_STRBUF_H */
