/*
 * jpeg_write.c - writing JPEG files through libjpeg (the IJG API,
 * libjpeg-turbo in practice): POV-Ray's +FJ.
 *
 * POV-Ray 3.7's reference ("Output File Type") fixes what matters: the
 * quality is 85 unless set, values 0 and 1 mean the default, 2 .. 100
 * are used as given; and "chroma sub-sampling has been disabled", so
 * every component is sampled 1 x 1 (4:4:4).  Samples are the sRGB codes
 * every 8-bit format here stores (image.c).  The file is baseline JFIF,
 * YCbCr, with libjpeg's standard tables scaled to the quality.
 *
 * libjpeg reports errors by calling error_exit, which by default prints
 * and exits: it is replaced by a longjmp back here, as in jpeg.c, and
 * warnings are dropped (an encoder's are about its own state, not about
 * data the user gave).
 */
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

#include "core/context.h"
#include "image/image.h"

/* The default quality (POV-Ray 3.7 reference, "Output File Type"). */
enum { DEFAULT_QUALITY = 85 };

typedef struct jpeg_out {
  struct jpeg_error_mgr mgr; /* first, so the two pointers coincide */
  jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
  struct jpeg_compress_struct cinfo;
  int cinfo_ready;
  unsigned char *row;
} jpeg_out;

static void on_error_exit(j_common_ptr cinfo) {
  jpeg_out *job = (jpeg_out *)cinfo->err;
  cinfo->err->format_message(cinfo, job->message);
  longjmp(job->jump, 1);
}

static void on_emit_message(j_common_ptr cinfo, int level) {
  (void)cinfo;
  (void)level;
}

/* Everything after the jump buffer is set (see zr__jpeg_encode). */
static zr_status encode_rows(jpeg_out *job, const zr_image *image,
                             const zr_image_encoding *e, FILE *f) {
  struct jpeg_compress_struct *ci = &job->cinfo;
  if (setjmp(job->jump))
    return ZR_EIO;
  jpeg_create_compress(ci);
  job->cinfo_ready = 1;
  jpeg_stdio_dest(ci, f);
  ci->image_width = (JDIMENSION)image->width;
  ci->image_height = (JDIMENSION)image->height;
  ci->input_components = 3;
  ci->in_color_space = JCS_RGB;
  jpeg_set_defaults(ci);
  int quality = e->quality <= 1 ? DEFAULT_QUALITY : e->quality;
  jpeg_set_quality(ci, quality, TRUE);
  for (int c = 0; c < ci->num_components; c++) {
    ci->comp_info[c].h_samp_factor = 1;
    ci->comp_info[c].v_samp_factor = 1;
  }
  jpeg_start_compress(ci, TRUE);
  while (ci->next_scanline < ci->image_height) {
    const float *src =
        image->pixels + (size_t)ci->next_scanline * image->width * 3;
    for (size_t i = 0; i < (size_t)image->width * 3; i++)
      job->row[i] =
          (unsigned char)zr__encode_code(src[i], e->assumed_gamma,
                                         e->file_gamma, 255);
    JSAMPROW rows[1] = {job->row};
    jpeg_write_scanlines(ci, rows, 1);
  }
  jpeg_finish_compress(ci);
  return ZR_OK;
}

zr_status zr__jpeg_encode(zr_context *ctx, const char *name,
                          const zr_image *image, const zr_image_encoding *e,
                          FILE *f) {
  /* JPEG's frame header holds 16-bit sizes. */
  if (image->width > 65500 || image->height > 65500)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ELIMIT, NULL,
                    "%s: JPEG files hold at most 65500 x 65500 pixels",
                    name);
  jpeg_out *job = calloc(1, sizeof *job);
  if (job)
    job->row = malloc((size_t)image->width * 3);
  if (!job || !job->row) {
    free(job);
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  }
  job->cinfo.err = jpeg_std_error(&job->mgr);
  job->mgr.error_exit = on_error_exit;
  job->mgr.emit_message = on_emit_message;
  zr_status s = encode_rows(job, image, e, f);
  if (s != ZR_OK)
    s = zr__diag(ctx, ZR_DIAG_ERROR, s, NULL, "%s: cannot write JPEG: %s",
                 name, job->message);
  if (job->cinfo_ready)
    jpeg_destroy_compress(&job->cinfo);
  free(job->row);
  free(job);
  return s;
}
