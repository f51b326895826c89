/*
 * numlist.c - the plain items of a mesh2 list, read straight from the
 * file's bytes.
 *
 * A mesh2 of a million vertices is an 80 MB file of little but
 * "<i, y, z>," items (reference manual, "Mesh2").  Lexing each number,
 * comma and bracket into a 24-byte token would cost hundreds of
 * megabytes and most of the parse time, so the lexer (tokens.c) hands
 * the run of plain items after a list's count to this reader instead and
 * keeps one token for the whole run (ZR_SDL_NUMBER_LIST); mesh2's fast
 * reader (build_mesh.c) reads the run again with the same function when
 * the grammar reaches it, so the two can never disagree on where the run
 * ends.
 *
 * An item is a vector of signed numbers, "<a, b, c>" (or "<a, b>" in
 * uv_vectors), followed by a comma, the next '<' or the list's '}' - the
 * items build_mesh.c's token reader takes.  Blanks may sit anywhere in
 * between, a comma may follow each item.  A number is what the scanner
 * (grammar/pov.l) calls one, and must be followed by a blank, ',', '>'
 * or (a sphere's radius, tokens.c) '}': anything else ("2a", "1.5.3", a
 * comment, an operator) ends the
 * run before the item, and the scanner and the grammar take over from
 * there exactly as if there had been no run.  Numbers convert exactly
 * like strtod(), which the scanner uses: with at most 19 significant
 * digits, a mantissa below 2^53 and a power of ten up to 22 both are
 * exact doubles and one IEEE division or product rounds correctly
 * (Clinger's fast path); any other number goes to strtod() itself.
 */
#include "config.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "sdl/sdl.h"

static const double powers_of_ten[23] = {
    1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};


static inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

static inline char at(const zr_sdl_numreader *r) {
  return r->pos < r->end ? r->bytes[r->pos] : '\0';
}

/* Moves past one byte on its line (not a newline). */
static inline void step(zr_sdl_numreader *r) {
  r->pos++;
  r->column++;
}

/*
 * The loops over bytes below keep the reader's place in local variables
 * and store it once at their end: the bytes are chars, which may alias
 * anything behind a pointer, so a loop that advanced r->pos reloaded and
 * stored it around each byte (callgrind: 240 instructions a number, half
 * of a terrain's parse; bench/parse.sh).
 */

/* Blanks, counting lines and columns as the scanner does. */
static inline void skip_blanks(zr_sdl_numreader *r) {
  r->pos = zr__sdl_skip_blanks(r->bytes, r->pos, r->end, &r->line,
                               &r->column);
}

/* The digits at p, before e, added to the mantissa (leading zeros are
   not significant, digits past the 19th only counted); the byte after
   them. */
static inline const char *digits_at(const char *p, const char *e,
                                    uint64_t *mantissa, int *digits) {
  uint64_t m = *mantissa;
  int n = *digits;
  for (; p < e && is_digit(*p); p++) {
    if (m || *p != '0') {
      if (n < 19)
        m = m * 10 + (uint64_t)(*p - '0');
      n++;
    }
  }
  *mantissa = m;
  *digits = n;
  return p;
}

/* The plain digits at p, before e, as one integer (exact while there
   are at most 19 of them); the byte after them. */
static inline const char *plain_digits(const char *p, const char *e,
                                       uint64_t *value) {
  uint64_t v = *value;
  for (; p < e && is_digit(*p); p++)
    v = v * 10 + (uint64_t)(*p - '0');
  *value = v;
  return p;
}

/*
 * Eight bytes at a time (SWAR: the bytes of one 64-bit word, the first
 * byte its lowest on a little-endian machine).  A sphere-heavy scene's
 * numbers are like "-0.042767": a few digits, a point, six digits; the
 * byte loop of plain_digits took ~187 instructions a number of
 * bench/peers.sh's sphereflake (callgrind).
 */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define SWAR_DIGITS 1
static const uint64_t powers_of_ten_int[8] = {
    1, 10, 100, 1000, 10000, 100000, 1000000, 10000000};

static inline uint64_t load8(const char *p) {
  uint64_t x;
  memcpy(&x, p, sizeof x);
  return x;
}

/* How many of the word's bytes, from the first, are digits (0 to 8).
   A byte is a digit when its high nibble is 3 and its low nibble plus 6
   stays below 16; each test stays within its byte (no carries). */
static inline int leading_digits(uint64_t x) {
  const uint64_t high = UINT64_C(0xF0F0F0F0F0F0F0F0);
  uint64_t not_3x = (x & high) ^ UINT64_C(0x3030303030303030);
  uint64_t over_9 =
      ((x & ~high) + UINT64_C(0x0606060606060606)) & high;
  uint64_t bad = not_3x | over_9; /* a nonzero byte: not a digit */
  return bad ? __builtin_ctzll(bad) / 8 : 8;
}

/* The value of the word's first n digits (1 <= n <= 8): they move to
   the top of the word behind 8 - n zero digits, and three multiplies
   add pairs, then fours, then the eight (each digit byte minus '0'
   holds 0-9; the bytes after the n digits, whose subtraction may have
   borrowed, are shifted out). */
static inline uint64_t digits_value(uint64_t x, int n) {
  uint64_t v = (x - UINT64_C(0x3030303030303030)) << (8 * (8 - n));
  v = v * 10 + (v >> 8); /* bytes 0, 2, 4, 6: two digits each */
  v = (((v & UINT64_C(0x000000FF000000FF)) * UINT64_C(0x000F424000000064)) +
       (((v >> 16) & UINT64_C(0x000000FF000000FF)) *
        UINT64_C(0x0000271000000001))) >>
      32;
  return v;
}
#else
#define SWAR_DIGITS 0
#endif

/*
 * The digits of a number before its exponent: DIGITS ["." DIGITS*] or
 * "." DIGITS, as the mantissa of its significant digits (digits past
 * the 19th only counted) and the number of digits after the point; the
 * byte after them, or NULL when there are none.  With at most 19 digits
 * in all (every number a scene writes with printf) one loop without
 * tests takes them, leading zeros adding nothing to the mantissa;
 * longer ones are read again digit by digit.
 */
static inline const char *mantissa_at(const char *start, const char *e,
                                      uint64_t *mantissa, int *digits,
                                      int *fraction) {
#if SWAR_DIGITS
  /* Fewer than 8 digits, a point, fewer than 8 digits (or no point),
     with 16 bytes to read: the same mantissa, digits, fraction and end
     as the loops below (tests/test_numlist.c compares them with strtod
     and with the loops on every length). */
  if (e - start >= 16) {
    uint64_t x = load8(start);
    int whole = leading_digits(x);
    if (whole < 8) {
      const char *p = start + whole;
      uint64_t m = whole ? digits_value(x, whole) : 0;
      if (*p != '.') {
        if (whole > 0) {
          *mantissa = m;
          *digits = m ? 1 : 0;
          *fraction = 0;
          return p;
        }
      } else {
        uint64_t y = load8(p + 1);
        int part = leading_digits(y);
        if (part < 8 && (whole > 0 || part > 0)) {
          m = m * powers_of_ten_int[part] + (part ? digits_value(y, part) : 0);
          *mantissa = m;
          *digits = m ? 1 : 0;
          *fraction = part;
          return p + 1 + part;
        }
      }
    }
  }
#endif
  uint64_t m = 0;
  const char *p = plain_digits(start, e, &m);
  bool any = p > start;
  const char *point = NULL;
  if (p < e && *p == '.' && (any || (p + 1 < e && is_digit(p[1])))) {
    point = p;
    p = plain_digits(p + 1, e, &m);
    any = true;
  }
  if (!any)
    return NULL;
  size_t all = (size_t)(p - start) - (point != NULL);
  *fraction = point ? (int)(p - point - 1) : 0;
  if (all <= 19) {
    *mantissa = m;
    *digits = m ? 1 : 0; /* only whether any is significant matters */
    return p;
  }
  m = 0;
  int n = 0;
  p = digits_at(start, e, &m, &n);
  if (point)
    p = digits_at(point + 1, e, &m, &n);
  *mantissa = m;
  *digits = n;
  return p;
}

/* A number as the scanner matches one: DIGITS ["." DIGITS*] [EXP] or
   "." DIGITS [EXP], EXP = [eE][-+]?DIGITS. */
static inline bool number(zr_sdl_numreader *r, double *out) {
  const char *start = r->bytes + r->pos, *e = r->bytes + r->end;
  uint64_t mantissa = 0;
  int digits = 0, fraction = 0;
  const char *p = mantissa_at(start, e, &mantissa, &digits, &fraction);
  if (!p)
    return false;
  int exponent = 0;
  bool exponent_ok = true;
  if (p < e && (*p == 'e' || *p == 'E')) {
    bool negative = p + 1 < e && p[1] == '-';
    const char *d = p + 1 < e && (p[1] == '-' || p[1] == '+') ? p + 2
                                                              : p + 1;
    if (d < e && is_digit(*d)) {
      for (p = d; p < e && is_digit(*p); p++) {
        if (exponent < 10000)
          exponent = exponent * 10 + (*p - '0');
        else
          exponent_ok = false;
      }
      if (negative)
        exponent = -exponent;
    }
  }
  /* The scanner would read what follows as another token (a '}' ends
     a sphere's radius; in an item only '>' and ',' go on). */
  char next = p < e ? *p : '\0';
  if (!(zr__sdl_is_blank(next) || next == ',' || next == '>' ||
        next == '}'))
    return false;
  int power = exponent - fraction;
  if (mantissa == 0 && digits == 0) {
    *out = 0.0;
  } else if (digits <= 19 && exponent_ok &&
             mantissa <= (UINT64_C(1) << 53) && power >= -22 &&
             power <= 22) {
    double m = (double)mantissa;
    *out = power < 0 ? m / powers_of_ten[-power] : m * powers_of_ten[power];
  } else {
    /* The character after the number stops strtod where the scanner
       stopped. */
    *out = strtod(start, NULL);
  }
  /* A number holds no newline: one column a byte. */
  r->pos += (size_t)(p - start);
  r->column += (int)(p - start);
  return true;
}

/* Signs, then a number: the token reader's "signed number". */
static inline bool signed_number(zr_sdl_numreader *r, double *out) {
  double sign = 1.0;
  while (at(r) == '-' || at(r) == '+') {
    if (at(r) == '-')
      sign = -sign;
    step(r);
    skip_blanks(r);
  }
  double v;
  if (!number(r, &v))
    return false;
  *out = sign * v;
  return true;
}

/* The reader works on a copy of its state that lives in registers (the
   bytes are chars, which may alias anything behind a pointer). */
static inline bool item(zr_sdl_numreader *r, double v[3], int *dim,
                        int *line, int *column) {
  zr_sdl_numreader start = *r;
  skip_blanks(r);
  if (at(r) == ',' && r->comma_ok) {
    step(r);
    skip_blanks(r);
  }
  if (at(r) != '<')
    goto not_an_item;
  *line = r->line;
  *column = r->column;
  step(r);
  int n = 0;
  for (;;) {
    skip_blanks(r);
    if (n == 3 || !signed_number(r, &v[n]))
      goto not_an_item;
    n++;
    skip_blanks(r);
    if (at(r) == '>')
      break;
    if (at(r) != ',')
      goto not_an_item;
    step(r);
  }
  step(r);
  if (n == 2 && r->uv)
    v[2] = 0.0;
  else if (n != 3)
    goto not_an_item;
  /* Complete only when nothing can continue it ("<1,2,3>*2" cannot be
     taken here). */
  zr_sdl_numreader after = *r;
  skip_blanks(&after);
  char next = at(&after);
  if (next != ',' && next != '<' && next != '}')
    goto not_an_item;
  *dim = n;
  r->comma_ok = true;
  return true;
not_an_item:
  *r = start;
  return false;
}

bool zr__sdl_numlist_item(zr_sdl_numreader *r, double v[3], int *dim,
                          int *line, int *column) {
  zr_sdl_numreader s = *r;
  bool ok = item(&s, v, dim, line, column);
  *r = s;
  return ok;
}

bool zr__sdl_numlist_sphere(zr_sdl_numreader *r, double v[4]) {
  zr_sdl_numreader s = *r;
  int dim, line, column;
  s.comma_ok = false;
  s.uv = false;
  if (!item(&s, v, &dim, &line, &column))
    return false;
  skip_blanks(&s);
  if (at(&s) != ',')
    return false;
  step(&s);
  skip_blanks(&s);
  if (!signed_number(&s, &v[3]))
    return false;
  *r = s;
  return true;
}
