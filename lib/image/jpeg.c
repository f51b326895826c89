/*
 * jpeg.c - JPEG reading through libjpeg (the IJG API, libjpeg-turbo in
 * practice), from memory.
 *
 * libjpeg's default error handler prints and calls exit(), which a
 * library must never do.  We replace error_exit with a longjmp back to
 * the decoder (the scheme of the IJG's example.c) and emit_message with
 * one that passes the first warning of a file on through the context
 * (corrupt data decodes to a damaged picture).  One warning is made an
 * error: libjpeg treats a file that ends early as a warning and pads the
 * picture with grey, which would hand the renderer a silently damaged
 * texture, so "premature end of JPEG file" becomes "truncated JPEG
 * file".
 *
 * Greyscale files stay one sample a pixel (image.h), colour files three;
 * libjpeg decodes the rows straight into the image's codes.  CMYK/YCCK files
 * are rejected by name.  JPEG pixels are taken as sRGB, as JFIF files are
 * in practice.
 */
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jerror.h>
#include <jpeglib.h>

#include "core/context.h"
#include "image/image.h"

/* The error manager extended with our jump buffer and message. */
typedef struct jpeg_job {
  struct jpeg_error_mgr mgr; /* first, so the two pointers coincide */
  jmp_buf jump;
  int truncated;
  int warned;
  char message[JMSG_LENGTH_MAX];
  struct jpeg_decompress_struct cinfo;
  int cinfo_ready;
  zr_image *image;
  zr_context *ctx;
  const char *name;
} jpeg_job;

static void on_error_exit(j_common_ptr cinfo) {
  jpeg_job *job = (jpeg_job *)cinfo->err;
  cinfo->err->format_message(cinfo, job->message);
  longjmp(job->jump, 1);
}

static void on_emit_message(j_common_ptr cinfo, int level) {
  jpeg_job *job = (jpeg_job *)cinfo->err;
  if (level >= 0)
    return; /* trace messages */
  if (cinfo->err->msg_code == JWRN_JPEG_EOF) {
    job->truncated = 1;
    longjmp(job->jump, 1);
  }
  /* Damaged data decodes to a damaged picture: say so once per file. */
  if (!job->warned) {
    char text[JMSG_LENGTH_MAX];
    cinfo->err->format_message(cinfo, text);
    zr__diag(job->ctx, ZR_DIAG_WARNING, ZR_EFORMAT, NULL, "%s: %s",
             job->name, text);
    job->warned = 1;
  }
}

/* Decodes after the jump buffer is set; see zr__jpeg_decode. */
static zr_status decode_rows(jpeg_job *job, const unsigned char *bytes,
                             size_t size) {
  struct jpeg_decompress_struct *ci = &job->cinfo;
  if (setjmp(job->jump))
    return ZR_EFORMAT;
  jpeg_create_decompress(ci);
  job->cinfo_ready = 1;
  jpeg_mem_src(ci, bytes, (unsigned long)size);
  jpeg_read_header(ci, TRUE);
  if (ci->jpeg_color_space == JCS_CMYK || ci->jpeg_color_space == JCS_YCCK)
    return zr__diag(job->ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: CMYK JPEG files are not supported", job->name);
  if (ci->num_components != 1)
    ci->out_color_space = JCS_RGB;
  /* The picture is allocated, and so charged to the memory budget,
     before the decoder starts: libjpeg's own buffers for a progressive
     or multi-scan file hold every coefficient of the picture (about as
     large as the picture), and a damaged header declaring 65500 x 65500
     made them grow to a gigabyte although the budget would have refused
     the picture (found by tests/fuzz/fuzz_image). */
  jpeg_calc_output_dimensions(ci);
  int comps = ci->output_components;
  if (comps != 1 && comps != 3)
    return zr__diag(job->ctx, ZR_DIAG_ERROR, ZR_EUNSUPPORTED, NULL,
                    "%s: JPEG with %d components is not supported",
                    job->name, comps);
  /* libjpeg's own memory is charged while it decodes: a progressive or
     multi-scan file keeps every DCT coefficient of the picture (64
     JCOEFs a block of each component, libjpeg.txt "Buffered-image
     mode"), a sequential one a strip of MCU rows (the largest vertical
     sampling factor times 8 lines of every component, twice for the
     context rows upsampling uses) and the output row. */
  size_t extra = 0;
  for (int c = 0; c < ci->num_components; c++) {
    const jpeg_component_info *comp = &ci->comp_info[c];
    if (jpeg_has_multiple_scans(ci))
      extra += (size_t)comp->width_in_blocks *
               (size_t)comp->height_in_blocks * DCTSIZE2 * sizeof(JCOEF);
    extra += 2 * (size_t)comp->width_in_blocks * DCTSIZE *
             (size_t)ci->max_v_samp_factor * DCTSIZE;
  }
  zr_status s = zr__image_new_coded(
      job->ctx, job->name, (int)ci->output_width, (int)ci->output_height,
      comps == 3 ? ZR_LAYOUT_RGB : ZR_LAYOUT_GREY, 255, ZR_TRANSFER_SRGB,
      0.0, extra, &job->image);
  if (s != ZR_OK)
    return s;
  jpeg_start_decompress(ci);
  unsigned char *codes = job->image->codes;
  size_t rowbytes = (size_t)ci->output_width * (size_t)comps;
  while (ci->output_scanline < ci->output_height) {
    JSAMPROW rows[1] = {codes + ci->output_scanline * rowbytes};
    if (jpeg_read_scanlines(ci, rows, 1) != 1)
      break;
  }
  jpeg_finish_decompress(ci);
  zr__image_release_extra(job->image, extra);
  return ZR_OK;
}

zr_status zr__jpeg_decode(zr_context *ctx, const char *name,
                          const unsigned char *bytes, size_t size,
                          zr_image **out) {
  jpeg_job *job = calloc(1, sizeof *job);
  if (!job)
    return zr__diag(ctx, ZR_DIAG_ERROR, ZR_ENOMEM, NULL, "%s: %s", name,
                    zr_status_str(ZR_ENOMEM));
  job->ctx = ctx;
  job->name = name;
  job->cinfo.err = jpeg_std_error(&job->mgr);
  job->mgr.error_exit = on_error_exit;
  job->mgr.emit_message = on_emit_message;
  zr_status s = decode_rows(job, bytes, size);
  if (s != ZR_OK && job->truncated)
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                 "%s: truncated JPEG file", name);
  else if (s != ZR_OK && job->message[0])
    s = zr__diag(ctx, ZR_DIAG_ERROR, ZR_EFORMAT, NULL,
                 "%s: invalid JPEG file: %s", name, job->message);
  if (job->cinfo_ready)
    jpeg_destroy_decompress(&job->cinfo);
  if (s == ZR_OK)
    *out = job->image;
  else
    zr_image_free(job->image);
  free(job);
  return s;
}
