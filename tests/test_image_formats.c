/*
 * test_image_formats.c - GIF, POT and TGA files (lib/image/gif.c,
 * lib/image/tga.c, lib/image/heights.c).  GIF:
 * a file ImageMagick wrote (interlaced, LZW with growing code widths),
 * files from a small LZW encoder of the test's own (a full 4096-entry
 * table that stays frozen, the code that names the entry being made,
 * every code size), POT heights, image_map and height_field scenes,
 * and broken files with their messages.  TGA: every image type read
 * (1, 2, 3 and their run-length encoded 9, 10, 11), pixel depths 8 to
 * 32, both origins, RLE packets across rows, heights, damaged files.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "image/image.h"
#include "zrcube.h"

/* ImageMagick 6's `convert g.ppm -interlace GIF g.gif` of a 29 x 23
   image whose pixel (x, y) has v = (x^2 + 3xy + y) mod 200 and colour
   (v, 255 - v, 7v mod 256): 200 colours, 8-bit LZW, interlaced. */
enum { MAGICK_W = 29, MAGICK_H = 23 };
static const unsigned char magick_gif[] = {
  0x47, 0x49, 0x46, 0x38, 0x39, 0x61, 0x1d, 0x00, 0x17, 0x00, 0xf7, 0x00,
  0x00, 0xb7, 0x48, 0x01, 0xb8, 0x47, 0x08, 0xb9, 0x46, 0x0f, 0xbb, 0x44,
  0x1d, 0x93, 0x6c, 0x05, 0x94, 0x6b, 0x0c, 0x95, 0x6a, 0x13, 0x96, 0x69,
  0x1a, 0xbc, 0x43, 0x24, 0xbd, 0x42, 0x2b, 0xbf, 0x40, 0x39, 0x97, 0x68,
  0x21, 0x98, 0x67, 0x28, 0x99, 0x66, 0x2f, 0x9a, 0x65, 0x36, 0x9b, 0x64,
  0x3d, 0xc0, 0x3f, 0x40, 0xc1, 0x3e, 0x47, 0xc3, 0x3c, 0x55, 0xc4, 0x3b,
  0x5c, 0xc5, 0x3a, 0x63, 0xc6, 0x39, 0x6a, 0xc7, 0x38, 0x71, 0x9c, 0x63,
  0x44, 0x9d, 0x62, 0x4b, 0x9e, 0x61, 0x52, 0x9f, 0x60, 0x59, 0xa0, 0x5f,
  0x60, 0xa1, 0x5e, 0x67, 0xa2, 0x5d, 0x6e, 0xa3, 0x5c, 0x75, 0xa4, 0x5b,
  0x7c, 0x6f, 0x90, 0x09, 0x70, 0x8f, 0x10, 0x71, 0x8e, 0x17, 0x72, 0x8d,
  0x1e, 0x4a, 0xb5, 0x06, 0x4c, 0xb3, 0x14, 0x4d, 0xb2, 0x1b, 0x73, 0x8c,
  0x25, 0x74, 0x8b, 0x2c, 0x75, 0x8a, 0x33, 0x4f, 0xb0, 0x29, 0x51, 0xae,
  0x37, 0x52, 0xad, 0x3e, 0x25, 0xda, 0x03, 0x27, 0xd8, 0x11, 0x28, 0xd7,
  0x18, 0x29, 0xd6, 0x1f, 0x00, 0xff, 0x00, 0x01, 0xfe, 0x07, 0x02, 0xfd,
  0x0e, 0x03, 0xfc, 0x15, 0x04, 0xfb, 0x1c, 0x2a, 0xd5, 0x26, 0x2c, 0xd3,
  0x34, 0x2d, 0xd2, 0x3b, 0x05, 0xfa, 0x23, 0x06, 0xf9, 0x2a, 0x07, 0xf8,
  0x31, 0x08, 0xf7, 0x38, 0x09, 0xf6, 0x3f, 0x77, 0x88, 0x41, 0x78, 0x87,
  0x48, 0x79, 0x86, 0x4f, 0x7a, 0x85, 0x56, 0x7b, 0x84, 0x5d, 0x53, 0xac,
  0x45, 0x54, 0xab, 0x4c, 0x55, 0xaa, 0x53, 0x56, 0xa9, 0x5a, 0x7c, 0x83,
  0x64, 0x7d, 0x82, 0x6b, 0x7f, 0x80, 0x79, 0x57, 0xa8, 0x61, 0x58, 0xa7,
  0x68, 0x59, 0xa6, 0x6f, 0x5a, 0xa5, 0x76, 0x5b, 0xa4, 0x7d, 0x2e, 0xd1,
  0x42, 0x2f, 0xd0, 0x49, 0x30, 0xcf, 0x50, 0x31, 0xce, 0x57, 0x32, 0xcd,
  0x5e, 0x0a, 0xf5, 0x46, 0x0b, 0xf4, 0x4d, 0x0c, 0xf3, 0x54, 0x0d, 0xf2,
  0x5b, 0x33, 0xcc, 0x65, 0x34, 0xcb, 0x6c, 0x35, 0xca, 0x73, 0x36, 0xc9,
  0x7a, 0x0e, 0xf1, 0x62, 0x0f, 0xf0, 0x69, 0x10, 0xef, 0x70, 0x11, 0xee,
  0x77, 0x12, 0xed, 0x7e, 0xa5, 0x5a, 0x83, 0xa6, 0x59, 0x8a, 0xa7, 0x58,
  0x91, 0xa8, 0x57, 0x98, 0xa9, 0x56, 0x9f, 0x81, 0x7e, 0x87, 0x82, 0x7d,
  0x8e, 0x83, 0x7c, 0x95, 0x84, 0x7b, 0x9c, 0xaa, 0x55, 0xa6, 0xac, 0x53,
  0xb4, 0xad, 0x52, 0xbb, 0x85, 0x7a, 0xa3, 0x86, 0x79, 0xaa, 0x87, 0x78,
  0xb1, 0x88, 0x77, 0xb8, 0x89, 0x76, 0xbf, 0xae, 0x51, 0xc2, 0xaf, 0x50,
  0xc9, 0xb0, 0x4f, 0xd0, 0xb1, 0x4e, 0xd7, 0xb2, 0x4d, 0xde, 0x8a, 0x75,
  0xc6, 0x8b, 0x74, 0xcd, 0x8c, 0x73, 0xd4, 0x8d, 0x72, 0xdb, 0xb3, 0x4c,
  0xe5, 0xb5, 0x4a, 0xf3, 0xb6, 0x49, 0xfa, 0x8e, 0x71, 0xe2, 0x90, 0x6f,
  0xf0, 0x91, 0x6e, 0xf7, 0x92, 0x6d, 0xfe, 0x5c, 0xa3, 0x84, 0x5d, 0xa2,
  0x8b, 0x5e, 0xa1, 0x92, 0x5f, 0xa0, 0x99, 0x61, 0x9e, 0xa7, 0x62, 0x9d,
  0xae, 0x63, 0x9c, 0xb5, 0x64, 0x9b, 0xbc, 0x37, 0xc8, 0x81, 0x38, 0xc7,
  0x88, 0x39, 0xc6, 0x8f, 0x3a, 0xc5, 0x96, 0x3b, 0xc4, 0x9d, 0x13, 0xec,
  0x85, 0x14, 0xeb, 0x8c, 0x15, 0xea, 0x93, 0x16, 0xe9, 0x9a, 0x3c, 0xc3,
  0xa4, 0x3d, 0xc2, 0xab, 0x3e, 0xc1, 0xb2, 0x3f, 0xc0, 0xb9, 0x17, 0xe8,
  0xa1, 0x18, 0xe7, 0xa8, 0x19, 0xe6, 0xaf, 0x1a, 0xe5, 0xb6, 0x1b, 0xe4,
  0xbd, 0x65, 0x9a, 0xc3, 0x66, 0x99, 0xca, 0x67, 0x98, 0xd1, 0x69, 0x96,
  0xdf, 0x40, 0xbf, 0xc0, 0x41, 0xbe, 0xc7, 0x42, 0xbd, 0xce, 0x43, 0xbc,
  0xd5, 0x44, 0xbb, 0xdc, 0x6a, 0x95, 0xe6, 0x6b, 0x94, 0xed, 0x6c, 0x93,
  0xf4, 0x6d, 0x92, 0xfb, 0x45, 0xba, 0xe3, 0x47, 0xb8, 0xf1, 0x48, 0xb7,
  0xf8, 0x49, 0xb6, 0xff, 0x1d, 0xe2, 0xcb, 0x1f, 0xe0, 0xd9, 0x20, 0xdf,
  0xe0, 0x21, 0xde, 0xe7, 0x22, 0xdd, 0xee, 0x23, 0xdc, 0xf5, 0x24, 0xdb,
  0xfc, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
  0x00, 0x21, 0xf9, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x2c, 0x00, 0x00,
  0x00, 0x00, 0x1d, 0x00, 0x17, 0x00, 0x40, 0x08, 0xfe, 0x00, 0x63, 0xc8,
  0xa8, 0xd1, 0xc3, 0x4b, 0xa6, 0x59, 0x52, 0x40, 0xad, 0x48, 0x04, 0xe4,
  0x4f, 0x99, 0x09, 0x99, 0x16, 0x31, 0x39, 0xc2, 0x21, 0x06, 0x0c, 0x22,
  0x66, 0xe8, 0x64, 0x2a, 0x61, 0x26, 0x00, 0x0f, 0x58, 0x93, 0x98, 0xfc,
  0x68, 0x80, 0x20, 0x13, 0xa8, 0x4f, 0x05, 0x22, 0xbc, 0x60, 0x92, 0x27,
  0x42, 0x94, 0x4f, 0x1f, 0x32, 0x2d, 0x69, 0x00, 0x89, 0xc9, 0x06, 0x58,
  0xa7, 0x04, 0x80, 0xf2, 0x12, 0x0a, 0x45, 0x19, 0x4c, 0x2b, 0xf2, 0xc8,
  0x00, 0x65, 0x66, 0x42, 0x28, 0x38, 0x3d, 0x88, 0x70, 0x78, 0x01, 0xa4,
  0x06, 0x13, 0x3a, 0xa1, 0x2e, 0x48, 0xf9, 0x03, 0x23, 0x0f, 0x8c, 0x3f,
  0x35, 0xbe, 0xbc, 0x92, 0x42, 0x8a, 0x49, 0x88, 0x38, 0x1f, 0x22, 0x60,
  0x62, 0x24, 0xc8, 0x0c, 0x99, 0x1e, 0x59, 0x0c, 0xfd, 0x89, 0x70, 0xc3,
  0x10, 0x83, 0x1e, 0xa4, 0xcc, 0x40, 0x60, 0x74, 0xc4, 0x8a, 0x94, 0x25,
  0x66, 0xd6, 0x7c, 0x01, 0x25, 0xe2, 0xc3, 0x97, 0x55, 0x66, 0x10, 0x48,
  0x09, 0x51, 0xe7, 0x86, 0x88, 0x00, 0x8c, 0xd2, 0xf4, 0x58, 0x52, 0x26,
  0x4b, 0x1c, 0x4c, 0x22, 0x6a, 0x40, 0x5a, 0xf1, 0xa7, 0x47, 0x09, 0x40,
  0x5e, 0x98, 0x7c, 0x80, 0xf1, 0x43, 0x06, 0x91, 0x32, 0x8b, 0x00, 0xcd,
  0x32, 0x83, 0x09, 0x08, 0x24, 0x20, 0x98, 0xcc, 0xcc, 0x02, 0xb4, 0xa8,
  0x0c, 0x91, 0x19, 0x3d, 0xc0, 0xb4, 0xb2, 0xc1, 0x88, 0xc4, 0xa0, 0x11,
  0x71, 0x3a, 0x24, 0x00, 0x23, 0x85, 0x45, 0x0a, 0x07, 0x11, 0x62, 0x99,
  0x08, 0x52, 0x06, 0x4c, 0xaa, 0x20, 0x75, 0x62, 0x0d, 0x72, 0xa0, 0x23,
  0xd3, 0x93, 0x54, 0x84, 0x80, 0x1c, 0xe0, 0xc3, 0x45, 0x8a, 0x11, 0x24,
  0x62, 0x7a, 0x6c, 0xe1, 0x74, 0x40, 0xc6, 0x16, 0x54, 0x62, 0x32, 0xfe,
  0x19, 0x31, 0xc0, 0x65, 0xc5, 0x81, 0x48, 0x84, 0xa8, 0xc0, 0x20, 0x81,
  0x2a, 0x90, 0x00, 0x4d, 0xa9, 0x46, 0x70, 0xa0, 0x42, 0x69, 0x44, 0x19,
  0x4d, 0x45, 0x02, 0xf5, 0x20, 0xa1, 0x87, 0xca, 0x0a, 0x07, 0xad, 0x94,
  0x22, 0x80, 0x28, 0x06, 0xc4, 0xc2, 0x05, 0x23, 0x9d, 0x18, 0x50, 0x81,
  0x14, 0x9d, 0x60, 0xc0, 0x05, 0x2b, 0x6e, 0x50, 0x50, 0x89, 0x19, 0x15,
  0xa4, 0xe2, 0xc7, 0x17, 0x84, 0xb0, 0xb1, 0x45, 0x1c, 0x92, 0xa0, 0x52,
  0x01, 0x13, 0x7d, 0x98, 0x20, 0x07, 0x18, 0xac, 0x9c, 0x91, 0xc0, 0x14,
  0x22, 0xd8, 0x81, 0xc3, 0x08, 0x02, 0x34, 0xd2, 0x06, 0x15, 0x4c, 0xa8,
  0xa1, 0xc5, 0x1d, 0x99, 0x8c, 0x90, 0xc3, 0x21, 0x11, 0x34, 0x91, 0x40,
  0x13, 0x11, 0x1c, 0x92, 0xc3, 0x08, 0x92, 0x30, 0x91, 0x41, 0x2b, 0x9d,
  0xd4, 0xb1, 0x45, 0x1b, 0x5c, 0x18, 0xd2, 0x47, 0x2a, 0x19, 0x48, 0xe1,
  0x47, 0x0b, 0x6e, 0xc0, 0xe2, 0x46, 0x0b, 0x7e, 0x48, 0x91, 0x41, 0x2a,
  0x7d, 0x18, 0xc2, 0x45, 0x1b, 0x5b, 0xc8, 0x90, 0x43, 0x15, 0x8f, 0xb4,
  0x02, 0x83, 0x22, 0xaa, 0x30, 0x81, 0x0a, 0x1a, 0x0f, 0xf0, 0xd1, 0x83,
  0x0b, 0xaa, 0x7c, 0xa2, 0xc7, 0x1e, 0x8f, 0x50, 0xf2, 0xc9, 0x02, 0x16,
  0x48, 0xc1, 0xc9, 0x03, 0x55, 0xa4, 0x42, 0xc3, 0x15, 0x99, 0xb8, 0xa0,
  0x08, 0x2b, 0x83, 0x9c, 0x80, 0x47, 0x18, 0x11, 0x5c, 0xa2, 0x08, 0x13,
  0x48, 0x78, 0x40, 0x03, 0x0e, 0x4c, 0xbc, 0x01, 0x00, 0x2c, 0x45, 0xe0,
  0x21, 0x81, 0x16, 0x22, 0xcc, 0xe1, 0x42, 0x0e, 0x91, 0xb8, 0xe0, 0xc8,
  0x0a, 0x9f, 0xa0, 0xa1, 0x41, 0x02, 0x91, 0x28, 0xe2, 0x84, 0x19, 0x65,
  0x54, 0xa1, 0x08, 0x27, 0x06, 0x58, 0x80, 0xc5, 0x27, 0x1c, 0x3c, 0xa2,
  0x82, 0x1e, 0xfe, 0x39, 0xa8, 0x82, 0x47, 0x0f, 0x3b, 0xb4, 0xa2, 0x85,
  0x0a, 0xa6, 0xc4, 0x51, 0x06, 0x0d, 0x2e, 0x98, 0x90, 0x82, 0x06, 0x34,
  0x48, 0x61, 0x08, 0x01, 0x16, 0x68, 0x81, 0xca, 0x18, 0x9b, 0x30, 0xd1,
  0xc0, 0x23, 0x4a, 0x60, 0xd0, 0x8a, 0x27, 0x7b, 0xf4, 0xd0, 0xc2, 0x28,
  0x88, 0xb4, 0x51, 0xc6, 0x0e, 0x50, 0x30, 0xd1, 0xc6, 0x1e, 0x9b, 0x98,
  0x60, 0x06, 0x00, 0x2e, 0x18, 0x82, 0xc1, 0x23, 0x43, 0x18, 0xf0, 0x85,
  0x12, 0x1a, 0xc0, 0x82, 0xca, 0x00, 0xa3, 0x18, 0x50, 0x05, 0x0e, 0x2b,
  0xf8, 0xa0, 0x81, 0x0c, 0x38, 0x38, 0x81, 0x47, 0x02, 0x30, 0x14, 0xb2,
  0x40, 0x0f, 0xa9, 0xa0, 0x21, 0x01, 0x25, 0x66, 0x58, 0xa0, 0x0a, 0x20,
  0x91, 0x20, 0xb2, 0x07, 0x25, 0x80, 0xb8, 0xe2, 0xc3, 0x15, 0x5a, 0x14,
  0x82, 0x87, 0x00, 0xb0, 0x0c, 0xf1, 0x46, 0x02, 0x38, 0x78, 0xe2, 0x41,
  0x26, 0x4c, 0x3c, 0x70, 0xc9, 0x20, 0x61, 0xb8, 0x70, 0x42, 0x04, 0xac,
  0x3c, 0xe0, 0x02, 0x12, 0x57, 0x78, 0x22, 0x01, 0x13, 0x5d, 0x50, 0x82,
  0x8a, 0x06, 0x55, 0x84, 0x02, 0xc4, 0x1e, 0x2e, 0x70, 0x12, 0x86, 0x2b,
  0x88, 0x94, 0x01, 0xc3, 0x09, 0x0a, 0xa4, 0x62, 0x80, 0x2b, 0x27, 0xc8,
  0xc0, 0xc4, 0x1e, 0xaa, 0x84, 0x41, 0x89, 0x06, 0x8e, 0x7c, 0x91, 0x8a,
  0x10, 0x7b, 0xb4, 0x60, 0x88, 0x06, 0x97, 0x30, 0x81, 0xc1, 0x26, 0x88,
  0xb0, 0x21, 0x45, 0x12, 0x3b, 0x30, 0xc1, 0x86, 0x23, 0x04, 0xb4, 0x60,
  0xc6, 0x25, 0x3e, 0x7c, 0x91, 0xc2, 0x23, 0x42, 0xb4, 0xf2, 0x88, 0x09,
  0x71, 0x58, 0x60, 0x89, 0x19, 0x14, 0x8c, 0x82, 0xc7, 0x15, 0x4c, 0x8c,
  0x01, 0x85, 0x19, 0x57, 0x20, 0x32, 0x80, 0x09, 0x65, 0x58, 0xa2, 0x01,
  0x23, 0x18, 0x38, 0xe2, 0x41, 0x2b, 0x2a, 0x75, 0x28, 0x61, 0x41, 0x24,
  0x45, 0x2c, 0xf0, 0x08, 0x13, 0x1c, 0xc8, 0x02, 0x42, 0x02, 0xa9, 0x2c,
  0x20, 0x0b, 0x10, 0x3d, 0x20, 0xa2, 0x40, 0x11, 0x7c, 0xa8, 0xb0, 0xc7,
  0x0a, 0x02, 0x38, 0x61, 0x01, 0x2a, 0x91, 0xbc, 0x81, 0x45, 0x19, 0x01,
  0x01, 0x00, 0x3b
};
enum { MAGICK_GIF_LEN = 1611 };

static unsigned magick_v(int x, int y) {
  return (unsigned)((x * x + 3 * y * x + y) % 200);
}

typedef struct fixture {
  zr_context *ctx;
  char dir[256];
  char path[512];
  char message[1024];
  char warning[1024];
  int errors, warnings;
} fixture;

static void catch_diag(const zr_diag *d, void *user) {
  fixture *fx = user;
  if (d->level == ZR_DIAG_ERROR) {
    fx->errors++;
    snprintf(fx->message, sizeof fx->message, "%s", d->message);
  } else if (d->level == ZR_DIAG_WARNING) {
    fx->warnings++;
    snprintf(fx->warning, sizeof fx->warning, "%s", d->message);
  }
}

static int setup(void **state) {
  fixture *fx = calloc(1, sizeof *fx);
  if (!fx)
    return -1;
  const char *tmp = getenv("TMPDIR");
  snprintf(fx->dir, sizeof fx->dir, "%s/zr-gif-XXXXXX",
           tmp && *tmp ? tmp : "/tmp");
  if (!mkdtemp(fx->dir) || zr_context_new(&fx->ctx) != ZR_OK) {
    free(fx);
    return -1;
  }
  /* The scenes are strings naming files in fx->dir, which is neither
     the working directory nor an include path: let them read there. */
  if (zr_context_add_read_path(fx->ctx, fx->dir) != ZR_OK)
    return -1;
  zr_context_set_diag(fx->ctx, catch_diag, fx);
  *state = fx;
  return 0;
}

static int teardown(void **state) {
  fixture *fx = *state;
  DIR *d = opendir(fx->dir);
  if (d) {
    struct dirent *e;
    while ((e = readdir(d))) {
      if (e->d_name[0] == '.')
        continue;
      char p[800];
      snprintf(p, sizeof p, "%s/%s", fx->dir, e->d_name);
      unlink(p);
    }
    closedir(d);
  }
  rmdir(fx->dir);
  zr_context_free(fx->ctx);
  free(fx);
  return 0;
}

static const char *in_dir(fixture *fx, const char *name) {
  snprintf(fx->path, sizeof fx->path, "%s/%s", fx->dir, name);
  return fx->path;
}

static void write_bytes(const char *path, const void *bytes, size_t n) {
  FILE *f = fopen(path, "wb");
  assert_non_null(f);
  assert_int_equal(fwrite(bytes, 1, n, f), n);
  assert_int_equal(fclose(f), 0);
}

/* ---- the test's own GIF writer ---- */

typedef struct gif_out {
  unsigned char *b;
  size_t n, cap;
  /* LZW bit packing into 255-byte sub-blocks */
  uint32_t acc;
  unsigned have;
  unsigned char block[255];
  unsigned block_n;
} gif_out;

static void put(gif_out *o, unsigned char c) {
  if (o->n == o->cap) {
    o->cap = o->cap ? 2 * o->cap : 4096;
    o->b = realloc(o->b, o->cap);
    assert_non_null(o->b);
  }
  o->b[o->n++] = c;
}

static void put16(gif_out *o, unsigned v) {
  put(o, (unsigned char)(v & 255));
  put(o, (unsigned char)(v >> 8));
}

static void flush_block(gif_out *o) {
  if (!o->block_n)
    return;
  put(o, (unsigned char)o->block_n);
  for (unsigned i = 0; i < o->block_n; i++)
    put(o, o->block[i]);
  o->block_n = 0;
}

static void put_code(gif_out *o, unsigned code, unsigned width) {
  o->acc |= (uint32_t)code << o->have;
  o->have += width;
  while (o->have >= 8) {
    o->block[o->block_n++] = (unsigned char)(o->acc & 255);
    o->acc >>= 8;
    o->have -= 8;
    if (o->block_n == 255)
      flush_block(o);
  }
}

/* A greedy LZW encoder (GIF89a appendix F) that never sends a clear
   code after the first, so a long enough image fills the table and
   goes on with it frozen. */
static void lzw_encode(gif_out *o, const unsigned char *idx, size_t n,
                       unsigned min_size) {
  static uint16_t child[4096][256]; /* 0: none */
  memset(child, 0, sizeof child);
  const unsigned clear = 1u << min_size, end = clear + 1;
  unsigned next = end + 1, width = min_size + 1;
  put(o, (unsigned char)min_size);
  put_code(o, clear, width);
  unsigned prefix = idx[0];
  for (size_t i = 1; i < n; i++) {
    unsigned c = idx[i];
    if (child[prefix][c]) {
      prefix = child[prefix][c];
      continue;
    }
    put_code(o, prefix, width);
    if (next < 4096) {
      child[prefix][c] = (uint16_t)next++;
      if (next > (1u << width) && width < 12)
        width++;
    }
    prefix = c;
  }
  put_code(o, prefix, width);
  if (next < 4096 && next + 1 > (1u << width) && width < 12)
    width++; /* the reader makes an entry after the last code too */
  put_code(o, end, width);
  if (o->have)
    put_code(o, 0, 8 - o->have);
  flush_block(o);
  put(o, 0);
}

/* A whole GIF89a file: w x h indices, a palette of 2^bits grey entries
   (entry k is grey k * 255 / (2^bits - 1)), an extension block before
   the image, interlaced or not. */
static gif_out make_gif(int w, int h, const unsigned char *idx,
                        unsigned bits, int interlaced) {
  gif_out o = {0};
  const char *sig = "GIF89a";
  for (int i = 0; i < 6; i++)
    put(&o, (unsigned char)sig[i]);
  put16(&o, (unsigned)w);
  put16(&o, (unsigned)h);
  put(&o, (unsigned char)(0x80 | (bits - 1) << 4 | (bits - 1)));
  put(&o, 0);
  put(&o, 0);
  unsigned entries = 1u << bits;
  for (unsigned k = 0; k < entries; k++)
    for (int c = 0; c < 3; c++)
      put(&o, (unsigned char)(k * 255 / (entries - 1)));
  /* A graphic control extension: read past. */
  const unsigned char gce[] = {0x21, 0xF9, 4, 1, 0, 0, 3, 0};
  for (size_t i = 0; i < sizeof gce; i++)
    put(&o, gce[i]);
  put(&o, 0x2C);
  put16(&o, 0);
  put16(&o, 0);
  put16(&o, (unsigned)w);
  put16(&o, (unsigned)h);
  put(&o, interlaced ? 0x40 : 0);
  size_t n = (size_t)w * (size_t)h;
  unsigned char *stored = malloc(n);
  assert_non_null(stored);
  if (interlaced) {
    static const int start[4] = {0, 4, 2, 1}, step[4] = {8, 8, 4, 2};
    size_t k = 0;
    for (int pass = 0; pass < 4; pass++)
      for (int y = start[pass]; y < h; y += step[pass])
        memcpy(stored + (k++) * (size_t)w, idx + (size_t)y * (size_t)w,
               (size_t)w);
  } else {
    memcpy(stored, idx, n);
  }
  lzw_encode(&o, stored, n, bits < 2 ? 2 : bits);
  free(stored);
  put(&o, 0x3B);
  return o;
}

/* ---- tests ---- */

static void test_gif_magick_file(void **state) {
  fixture *fx = *state;
  zr_gif_indices g;
  assert_int_equal(zr__gif_decode_indices(fx->ctx, "m.gif", magick_gif,
                                          MAGICK_GIF_LEN, &g),
                   ZR_OK);
  assert_int_equal(g.width, MAGICK_W);
  assert_int_equal(g.height, MAGICK_H);
  /* Every pixel's palette entry holds its colour. */
  for (int y = 0; y < MAGICK_H; y++)
    for (int x = 0; x < MAGICK_W; x++) {
      unsigned k = g.indices[y * MAGICK_W + x];
      assert_true((int)k < g.palette_size);
      unsigned v = magick_v(x, y);
      assert_int_equal(g.palette[3 * k], v);
      assert_int_equal(g.palette[3 * k + 1], 255 - v);
      assert_int_equal(g.palette[3 * k + 2], (7 * v) % 256);
    }
  free(g.indices);
  /* As an image: the codes are the palette's, the colours sRGB. */
  zr_image *im = NULL;
  assert_int_equal(zr__gif_decode(fx->ctx, "m.gif", magick_gif,
                                  MAGICK_GIF_LEN, &im),
                   ZR_OK);
  assert_non_null(im->indices);
  assert_int_equal(im->maxval, 255);
  unsigned v = magick_v(5, 17);
  size_t i = 17 * MAGICK_W + 5;
  assert_int_equal(zr__image_stored(im, 3 * i), v);
  assert_int_equal(zr__image_stored(im, 3 * i + 1), 255 - v);
  assert_true(fabs(zr__image_linear(im, 3 * i) - zr__srgb_decode(v / 255.0)) <
              1e-6);
  zr_image_free(im);
  assert_int_equal(fx->errors, 0);
  assert_int_equal(fx->warnings, 0);
}

/* A pseudo-random image: long runs and noise, so the table fills. */
static unsigned char *noise(size_t n, unsigned bits) {
  unsigned char *idx = malloc(n);
  assert_non_null(idx);
  uint32_t s = 12345;
  for (size_t i = 0; i < n; i++) {
    s = s * 1103515245u + 12345u;
    unsigned r = (s >> 16) & 0x7fff;
    idx[i] = (unsigned char)((r % 7 == 0 ? r : i / 97 + (r & 1)) &
                             ((1u << bits) - 1));
  }
  return idx;
}

static void round_trip(fixture *fx, int w, int h, unsigned bits,
                       int interlaced) {
  size_t n = (size_t)w * (size_t)h;
  unsigned char *idx = noise(n, bits);
  gif_out o = make_gif(w, h, idx, bits, interlaced);
  zr_gif_indices g;
  assert_int_equal(zr__gif_decode_indices(fx->ctx, "r.gif", o.b, o.n, &g),
                   ZR_OK);
  assert_int_equal(g.width, w);
  assert_int_equal(g.height, h);
  assert_int_equal(g.palette_size, 1 << bits);
  assert_memory_equal(g.indices, idx, n);
  free(g.indices);
  free(idx);
  free(o.b);
}

static void test_gif_round_trips(void **state) {
  fixture *fx = *state;
  round_trip(fx, 300, 200, 8, 0); /* 60,000 pixels: the table fills */
  round_trip(fx, 300, 200, 8, 1);
  round_trip(fx, 17, 13, 1, 1);   /* 2 colours, code size 2 */
  round_trip(fx, 64, 3, 4, 0);
  round_trip(fx, 1, 1, 8, 0);
  round_trip(fx, 5, 9, 8, 1);     /* fewer rows than a pass's step */
  /* One colour throughout: every code names the entry being made. */
  unsigned char flat[4000];
  memset(flat, 3, sizeof flat);
  gif_out o = make_gif(80, 50, flat, 2, 0);
  zr_gif_indices g;
  assert_int_equal(zr__gif_decode_indices(fx->ctx, "f.gif", o.b, o.n, &g),
                   ZR_OK);
  assert_memory_equal(g.indices, flat, sizeof flat);
  free(g.indices);
  free(o.b);
  assert_int_equal(fx->errors, 0);
  assert_int_equal(fx->warnings, 0);
}

/* POT: the left half's entries are high bytes, the right half's low. */
static void test_gif_pot_heights(void **state) {
  fixture *fx = *state;
  enum { W = 4, H = 3 };
  unsigned char idx[H][2 * W];
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++) {
      unsigned v = (unsigned)(x * 20000 + y * 1234 + 7);
      idx[y][x] = (unsigned char)(v >> 8);
      idx[y][W + x] = (unsigned char)(v & 255);
    }
  gif_out o = make_gif(2 * W, H, &idx[0][0], 8, 0);
  write_bytes(in_dir(fx, "h.pot"), o.b, o.n);
  float *heights = NULL;
  int w = 0, h = 0;
  assert_int_equal(zr__image_read_heights(fx->ctx, fx->path, true, &heights,
                                          &w, &h),
                   ZR_OK);
  assert_int_equal(w, W);
  assert_int_equal(h, H);
  for (int y = 0; y < H; y++)
    for (int x = 0; x < W; x++)
      assert_true(fabs(heights[y * W + x] -
                       (x * 20000 + y * 1234 + 7) / 65535.0) < 1e-6);
  free(heights);
  /* The same file as a GIF height field: index / 255. */
  assert_int_equal(zr__image_read_heights(fx->ctx, fx->path, false,
                                          &heights, &w, &h),
                   ZR_OK);
  assert_int_equal(w, 2 * W);
  assert_true(fabs(heights[1] - idx[0][1] / 255.0) < 1e-6);
  free(heights);
  free(o.b);
  /* A POT file must be a GIF, of even width. */
  unsigned char odd[3 * 2] = {0};
  o = make_gif(3, 2, odd, 8, 0);
  write_bytes(in_dir(fx, "odd.pot"), o.b, o.n);
  assert_int_equal(zr__image_read_heights(fx->ctx, fx->path, true, &heights,
                                          &w, &h),
                   ZR_EFORMAT);
  assert_non_null(strstr(fx->message, "twice as wide"));
  free(o.b);
  write_bytes(in_dir(fx, "p.pot"), "P2 2 2 255 0 0 0 0\n", 19);
  assert_int_equal(zr__image_read_heights(fx->ctx, fx->path, true, &heights,
                                          &w, &h),
                   ZR_EFORMAT);
  assert_non_null(strstr(fx->message, "not a POT file"));
}

/* Scenes: an image_map and a pot height field from files. */
static void test_gif_in_scenes(void **state) {
  fixture *fx = *state;
  write_bytes(in_dir(fx, "m.gif"), magick_gif, MAGICK_GIF_LEN);
  char text[2048];
  snprintf(text, sizeof text,
           "#version 3.7;\n"
           "camera { orthographic location <0.5, 0.5, -1> "
           "look_at <0.5, 0.5, 0> right x up y }\n"
           "plane { z, 0 pigment { image_map { gif \"%s/m.gif\" } }\n"
           "  finish { ambient 1 diffuse 0 } }\n",
           fx->dir);
  zr_scene *scene = NULL;
  assert_int_equal(zr_scene_parse_string(fx->ctx, "t.pov", text, strlen(text), &scene),
                   ZR_OK);
  zr_render_params rp;
  zr_render_params_init(&rp);
  rp.width = MAGICK_W;
  rp.height = MAGICK_H;
  float *rgb = malloc((size_t)MAGICK_W * MAGICK_H * 3 * sizeof *rgb);
  assert_non_null(rgb);
  assert_int_equal(zr_render_image(scene, &rp, rgb, NULL), ZR_OK);
  /* The picture is the file's pixels. */
  for (int y = 0; y < MAGICK_H; y += 3)
    for (int x = 0; x < MAGICK_W; x += 2) {
      const float *px = rgb + 3 * ((size_t)y * MAGICK_W + (size_t)x);
      assert_true(fabs(px[1] - zr__srgb_decode((255 - magick_v(x, y)) /
                                               255.0)) < 1e-3);
    }
  free(rgb);
  zr_scene_free(scene);
  /* A POT height field: 2 x 2 samples of (256 hi + lo) / 65535. */
  unsigned char pot[2][4] = {{0x80, 0xFF, 0x00, 0xFF}, {0, 0, 0, 0}};
  gif_out o = make_gif(4, 2, &pot[0][0], 8, 0);
  write_bytes(in_dir(fx, "t.pot"), o.b, o.n);
  free(o.b);
  snprintf(text, sizeof text,
           "height_field { pot \"%s/t.pot\" }\n", fx->dir);
  assert_int_equal(zr_scene_parse_string(fx->ctx, "t.pov", text, strlen(text), &scene),
                   ZR_OK);
  zr_scene_free(scene);
  /* A missing one is named. */
  snprintf(text, sizeof text, "height_field { pot \"%s/no.pot\" }\n",
           fx->dir);
  assert_int_equal(zr_scene_parse_string(fx->ctx, "t.pov", text, strlen(text), &scene),
                   ZR_ENOTFOUND);
}

static void test_gif_broken_files(void **state) {
  fixture *fx = *state;
  zr_gif_indices g;
  struct {
    size_t cut; /* bytes kept of the ImageMagick file, 0: all */
    const char *patch;
    size_t at;
    const char *message;
  } cases[] = {
      {10, NULL, 0, "b.gif: not a GIF file"},
      {400, NULL, 0, "b.gif: truncated GIF colour table"},
      {0, "GIF88a", 0, "b.gif: unknown GIF version (not 87a or 89a)"},
      {0, "\x3b", 13 + 768, "b.gif: GIF file without an image"},
      {0, "\x55", 13 + 768, "b.gif: damaged GIF file (unknown block)"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    unsigned char copy[MAGICK_GIF_LEN];
    memcpy(copy, magick_gif, MAGICK_GIF_LEN);
    if (cases[i].patch)
      memcpy(copy + cases[i].at, cases[i].patch, strlen(cases[i].patch));
    size_t n = cases[i].cut ? cases[i].cut : MAGICK_GIF_LEN;
    fx->errors = 0;
    assert_int_equal(zr__gif_decode_indices(fx->ctx, "b.gif", copy, n, &g),
                     ZR_EFORMAT);
    assert_int_equal(fx->errors, 1);
    assert_string_equal(fx->message, cases[i].message);
    assert_null(g.indices);
  }
  /* Data cut short: what was decoded stays, with a warning. */
  unsigned char idx[300 * 200];
  memset(idx, 0, sizeof idx);
  unsigned char *rnd = noise(sizeof idx, 8);
  gif_out o = make_gif(300, 200, rnd, 8, 0);
  size_t head = 13 + 768 + 8 + 10 + 1;
  fx->warnings = 0;
  assert_int_equal(
      zr__gif_decode_indices(fx->ctx, "c.gif", o.b, head + 2000, &g), ZR_OK);
  assert_int_equal(fx->warnings, 1);
  assert_non_null(strstr(fx->warning, "GIF image data ends after"));
  assert_memory_equal(g.indices, rnd, 1000); /* the start is right */
  free(g.indices);
  /* A code past the table is an error, not a guess. */
  o.b[head + 2] ^= 0xF0;
  o.b[head + 3] ^= 0xFF;
  fx->errors = 0;
  zr_status s = zr__gif_decode_indices(fx->ctx, "d.gif", o.b, o.n, &g);
  if (s == ZR_OK) {
    /* Flipped bits may still make valid codes: then the pixels differ. */
    assert_true(memcmp(g.indices, rnd, sizeof idx) != 0);
    free(g.indices);
  } else {
    assert_int_equal(s, ZR_EFORMAT);
    assert_string_equal(fx->message,
                        "d.gif: damaged GIF image data (invalid LZW code)");
  }
  free(o.b);
  free(rnd);
  /* A zero-sized image. */
  unsigned char one = 0;
  o = make_gif(1, 1, &one, 8, 0);
  o.b[13 + 768 + 8 + 5] = 0; /* width 0 */
  assert_int_equal(zr__gif_decode_indices(fx->ctx, "z.gif", o.b, o.n, &g),
                   ZR_EFORMAT);
  assert_string_equal(fx->message, "z.gif: invalid image size 0x1");
  free(o.b);
}


/* ---- TGA ---- */

/* A TGA file of the test's own: w x h pixels given as codes (r, g, b),
   written in the type's pixel format; rle packs runs of equal pixels
   (and raw packets between them) across rows; top_down sets bit 5. */
static gif_out make_tga(int w, int h, const unsigned char *rgb,
                        unsigned type, unsigned depth, int top_down) {
  gif_out o = {0};
  unsigned base = type & 7;
  put(&o, 2); /* an image ID of two bytes, skipped */
  put(&o, base == 1 ? 1 : 0);
  put(&o, (unsigned char)type);
  /* The colour map: entry k is grey k (24 bits); first entry 0. */
  put16(&o, 0);
  put16(&o, base == 1 ? 256 : 0);
  put(&o, base == 1 ? 24 : 0);
  put16(&o, 0);
  put16(&o, 0);
  put16(&o, (unsigned)w);
  put16(&o, (unsigned)h);
  put(&o, (unsigned char)depth);
  put(&o, (unsigned char)((top_down ? 0x20 : 0) | (depth == 32 ? 8 : 0)));
  put(&o, 'I');
  put(&o, 'D');
  if (base == 1)
    for (unsigned k = 0; k < 256; k++)
      for (int c = 0; c < 3; c++)
        put(&o, (unsigned char)k);
  size_t n = (size_t)w * (size_t)h;
  unsigned bytes = (depth + 7) / 8;
  unsigned char *px = malloc(n * bytes);
  assert_non_null(px);
  for (size_t i = 0; i < n; i++) {
    size_t r = i / (size_t)w, c = i % (size_t)w;
    size_t y = top_down ? r : (size_t)h - 1 - r;
    const unsigned char *s = rgb + 3 * (y * (size_t)w + c);
    unsigned char *d = px + i * bytes;
    if (base == 1 || base == 3) {
      d[0] = s[0];
      if (depth == 16)
        d[1] = 255; /* grey 16: grey and alpha */
    } else if (depth == 16 || depth == 15) {
      unsigned v = (unsigned)(s[0] >> 3) << 10 | (unsigned)(s[1] >> 3) << 5 |
                   (unsigned)(s[2] >> 3);
      d[0] = (unsigned char)(v & 255);
      d[1] = (unsigned char)(v >> 8);
    } else {
      d[0] = s[2];
      d[1] = s[1];
      d[2] = s[0];
      if (depth == 32)
        d[3] = 128;
    }
  }
  if (type < 9) {
    for (size_t i = 0; i < n * bytes; i++)
      put(&o, px[i]);
  } else {
    size_t i = 0;
    while (i < n) {
      size_t run = 1;
      while (i + run < n && run < 128 &&
             !memcmp(px + (i + run) * bytes, px + i * bytes, bytes))
        run++;
      if (run > 1) {
        put(&o, (unsigned char)(0x80 | (run - 1)));
        for (unsigned b = 0; b < bytes; b++)
          put(&o, px[i * bytes + b]);
        i += run;
        continue;
      }
      size_t raw = 1;
      while (i + raw < n && raw < 128 &&
             (i + raw + 1 >= n ||
              memcmp(px + (i + raw + 1) * bytes, px + (i + raw) * bytes,
                     bytes)))
        raw++;
      put(&o, (unsigned char)(raw - 1));
      for (size_t b = 0; b < raw * bytes; b++)
        put(&o, px[i * bytes + b]);
      i += raw;
    }
  }
  free(px);
  return o;
}

/* Codes of a test picture: runs along rows and a few odd pixels. */
static unsigned char *tga_picture(int w, int h, int grey) {
  unsigned char *rgb = malloc((size_t)w * (size_t)h * 3);
  assert_non_null(rgb);
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      unsigned char *p = rgb + 3 * ((size_t)y * (size_t)w + (size_t)x);
      unsigned v = (unsigned)((x / 5) * 40 + y * 3 + ((x * y) % 7 == 3)) & 255;
      p[0] = (unsigned char)v;
      p[1] = (unsigned char)(grey ? v : 255 - v);
      p[2] = (unsigned char)(grey ? v : (v * 5) & 255);
    }
  return rgb;
}

static void tga_case(fixture *fx, unsigned type, unsigned depth,
                     int top_down) {
  enum { W = 37, H = 11 };
  unsigned base = type & 7;
  unsigned char *rgb = tga_picture(W, H, base != 2);
  gif_out o = make_tga(W, H, rgb, type, depth, top_down);
  zr_image *im = NULL;
  assert_int_equal(zr__tga_decode(fx->ctx, "t.tga", o.b, o.n, &im), ZR_OK);
  assert_int_equal(zr_image_width(im), W);
  assert_int_equal(zr_image_height(im), H);
  for (size_t i = 0; i < (size_t)W * H; i++)
    for (int c = 0; c < 3; c++) {
      unsigned want = rgb[3 * i + c];
      if (depth == 15 || depth == 16) {
        if (base == 2)
          want = (want >> 3) * 255 / 31;
      }
      if (zr__image_stored(im, 3 * i + c) != want)
        fail_msg("type %u depth %u: pixel %zu channel %d is %u, not %u",
                 type, depth, i, c, zr__image_stored(im, 3 * i + c), want);
    }
  if (base == 1) {
    assert_non_null(im->indices);
    assert_int_equal(im->indices[5], rgb[15]);
  }
  assert_true(fabs(zr__image_linear(im, 3) -
                   zr__srgb_decode(rgb[3] / 255.0)) < 1e-6);
  zr_image_free(im);
  free(o.b);
  free(rgb);
}

static void test_tga_types(void **state) {
  fixture *fx = *state;
  const unsigned types[] = {1, 2, 3, 9, 10, 11};
  for (size_t t = 0; t < sizeof types / sizeof *types; t++) {
    unsigned base = types[t] & 7;
    for (int top = 0; top < 2; top++) {
      if (base == 2) {
        tga_case(fx, types[t], 24, top);
        tga_case(fx, types[t], 32, top);
        tga_case(fx, types[t], 16, top);
      } else {
        tga_case(fx, types[t], 8, top);
      }
    }
  }
  tga_case(fx, 3, 16, 1);
  assert_int_equal(fx->errors, 0);
}

/* Heights: grey v / 255, colour (256 r + g) / 65535, as the manual's
   "red and green bytes ... high and low bytes" of a 16-bit height. */
static void test_tga_heights_and_scenes(void **state) {
  fixture *fx = *state;
  unsigned char rgb[2 * 2 * 3] = {0x12, 0x34, 0, 0xFF, 0xFF, 0,
                                  0, 1, 0, 0, 0, 0};
  gif_out o = make_tga(2, 2, rgb, 10, 24, 0);
  write_bytes(in_dir(fx, "h.tga"), o.b, o.n);
  free(o.b);
  float *heights = NULL;
  int w = 0, h = 0;
  assert_int_equal(zr__image_read_heights(fx->ctx, fx->path, false,
                                          &heights, &w, &h),
                   ZR_OK);
  assert_true(fabs(heights[0] - 0x1234 / 65535.0) < 1e-7);
  assert_true(fabs(heights[1] - 1.0) < 1e-7);
  assert_true(fabs(heights[2] - 1 / 65535.0) < 1e-7);
  free(heights);
  unsigned char grey[2 * 2 * 3] = {51, 51, 51, 0, 0, 0, 0, 0, 0, 255, 255, 255};
  o = make_tga(2, 2, grey, 3, 8, 1);
  write_bytes(in_dir(fx, "g.tga"), o.b, o.n);
  free(o.b);
  assert_int_equal(zr__image_read_heights(fx->ctx, fx->path, false,
                                          &heights, &w, &h),
                   ZR_OK);
  assert_true(fabs(heights[0] - 0.2) < 1e-7);
  assert_true(fabs(heights[3] - 1.0) < 1e-7);
  free(heights);
  /* Through the parser, with and without the type keyword. */
  char text[1024];
  zr_scene *scene = NULL;
  snprintf(text, sizeof text,
           "height_field { tga \"%s/h.tga\" }\n"
           "height_field { \"%s/g.tga\" }\n"
           "plane { y, 0 pigment { image_map { tga \"%s/h.tga\" } } }\n",
           fx->dir, fx->dir, fx->dir);
  assert_int_equal(zr_scene_parse_string(fx->ctx, "t.pov", text,
                                         strlen(text), &scene),
                   ZR_OK);
  zr_scene_free(scene);
}

static void test_tga_broken_files(void **state) {
  fixture *fx = *state;
  unsigned char rgb[4 * 3 * 3];
  memset(rgb, 7, sizeof rgb);
  gif_out o = make_tga(4, 3, rgb, 2, 24, 0);
  zr_image *im = NULL;
  /* Cut short. */
  assert_int_equal(zr__tga_decode(fx->ctx, "t.tga", o.b, o.n - 1, &im),
                   ZR_EFORMAT);
  assert_string_equal(fx->message, "t.tga: truncated TGA file (pixels)");
  assert_null(im);
  /* An image type that is not read (32: Huffman). */
  o.b[2] = 32;
  assert_int_equal(zr__tga_decode(fx->ctx, "t.tga", o.b, o.n, &im),
                   ZR_EFORMAT);
  assert_non_null(strstr(fx->message, "not a TGA file"));
  /* 8-bit true colour. */
  o.b[2] = 2;
  o.b[16] = 8;
  assert_int_equal(zr__tga_decode(fx->ctx, "t.tga", o.b, o.n, &im),
                   ZR_EFORMAT);
  assert_string_equal(fx->message,
                      "t.tga: damaged TGA file (8-bit true colour)");
  free(o.b);
  /* A colour map that runs past the end. */
  o = make_tga(4, 3, rgb, 1, 8, 0);
  assert_int_equal(zr__tga_decode(fx->ctx, "t.tga", o.b, 100, &im),
                   ZR_EFORMAT);
  assert_string_equal(fx->message, "t.tga: truncated TGA file (colour map)");
  /* RLE data cut inside a packet. */
  free(o.b);
  o = make_tga(4, 3, rgb, 10, 24, 0);
  assert_int_equal(zr__tga_decode(fx->ctx, "t.tga", o.b, o.n - 2, &im),
                   ZR_EFORMAT);
  assert_string_equal(fx->message, "t.tga: truncated TGA file (pixels)");
  free(o.b);
  /* A file named .tga that is something else. */
  write_bytes(in_dir(fx, "x.tga"), "hello", 5);
  assert_int_equal(zr_image_read(fx->ctx, fx->path, &im), ZR_EFORMAT);
  assert_non_null(strstr(fx->message, "x.tga: not a TGA file"));
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_setup_teardown(test_gif_magick_file, setup, teardown),
      cmocka_unit_test_setup_teardown(test_gif_round_trips, setup, teardown),
      cmocka_unit_test_setup_teardown(test_gif_pot_heights, setup, teardown),
      cmocka_unit_test_setup_teardown(test_gif_in_scenes, setup, teardown),
      cmocka_unit_test_setup_teardown(test_gif_broken_files, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_tga_types, setup, teardown),
      cmocka_unit_test_setup_teardown(test_tga_heights_and_scenes, setup,
                                      teardown),
      cmocka_unit_test_setup_teardown(test_tga_broken_files, setup,
                                      teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
