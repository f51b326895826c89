/*
 * test_cli_options.c - the zrcube command line (bin/options.c): POV-Ray
 * switches, GNU long options, INI options and files, the checks on every
 * value with their exact messages, and the image file name.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "options.h"

/* Parses a NULL-terminated list of words into o (initialised here). */
static int parse_words(zr_cli_options *o, char *err,
                       const char *const *words) {
  zr_render_params defaults;
  zr_render_params_init(&defaults);
  zr__cli_init(o, &defaults);
  int argc = 1;
  char *argv[32] = {"zrcube"};
  for (; words[argc - 1]; argc++)
    argv[argc] = (char *)words[argc - 1];
  return zr__cli_parse(o, argc, argv, err, 512);
}

#define PARSE(o, err, ...)                                                 \
  parse_words((o), (err), (const char *[]){__VA_ARGS__, NULL})

/* Asserts that the words fail with exactly this message. */
#define EXPECT_ERROR(message, ...)                                         \
  do {                                                                     \
    zr_cli_options o_;                                                     \
    char err_[512];                                                        \
    assert_int_equal(PARSE(&o_, err_, __VA_ARGS__), -1);                   \
    assert_string_equal(err_, message);                                    \
    zr__cli_free(&o_);                                                     \
  } while (0)

static void test_cli_options_defaults(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  zr_render_params defaults;
  zr_render_params_init(&defaults);
  assert_int_equal(PARSE(&o, err, "scene.pov"), 0);
  assert_string_equal(o.input, "scene.pov");
  assert_null(o.output);
  assert_memory_equal(&o.params, &defaults, sizeof defaults);
  assert_int_equal(o.threads, 0);
  assert_int_equal(o.format, ZR_FORMAT_AUTO);
  assert_true(o.write_output);
  assert_false(o.verbose || o.quiet || o.help || o.version);
  zr__cli_free(&o);
}

static void test_cli_options_povray_switches(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "+W640", "+h480", "+A0.1", "+R4",
                         "+J0.5", "+wt3", "+Linc", "+L/usr/inc", "+Linc",
                         "+Oout.png", "-D", "+D0", "+P", "+V", "+Iscene.pov",
                         "+AM1", "+FN16"),
                   0);
  assert_string_equal(o.input, "scene.pov");
  assert_string_equal(o.output, "out.png");
  assert_int_equal(o.params.width, 640);
  assert_int_equal(o.params.height, 480);
  assert_int_equal(o.params.antialias, 1);
  /* Exact: 0.1 is parsed once by strtod on both sides. */
  assert_true(o.params.aa_threshold == 0.1);
  assert_int_equal(o.params.aa_depth, 4);
  assert_int_equal(o.params.jitter, 1);
  assert_true(o.params.jitter_amount == 0.5);
  assert_int_equal(o.threads, 3);
  /* A path given twice counts once, as in POV-Ray. */
  assert_int_equal(o.n_include_paths, 2);
  assert_string_equal(o.include_paths[0], "inc");
  assert_string_equal(o.include_paths[1], "/usr/inc");
  assert_int_equal(o.verbose, 1);
  assert_int_equal(o.format, ZR_FORMAT_PNG16);
  zr__cli_free(&o);
}

static void test_cli_options_switches_turn_off(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "+A", "-A0.2", "+J", "-J", "s.pov", "+V",
                         "-V", "-F"),
                   0);
  assert_int_equal(o.params.antialias, 0);
  assert_true(o.params.aa_threshold == 0.2);
  assert_int_equal(o.params.jitter, 0);
  assert_int_equal(o.verbose, 0);
  assert_int_equal(o.write_output, 0);
  zr__cli_free(&o);
  /* POV-Ray: a jitter amount of 0 or less turns jitter off. */
  assert_int_equal(PARSE(&o, err, "+J", "+J0", "s.pov"), 0);
  assert_int_equal(o.params.jitter, 0);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "-h"), 0);
  assert_int_equal(o.help, 1);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "-v", "+FP"), 0);
  assert_int_equal(o.verbose, 1);
  assert_int_equal(o.format, ZR_FORMAT_PPM);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "-q"), 0);
  assert_int_equal(o.quiet, 1);
  zr__cli_free(&o);
}

static void test_cli_options_long_options(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "--width=5", "--height", "7",
                         "--antialias", "--aa-depth=2", "--threads", "4",
                         "--include-path=a", "--include-path", "b",
                         "--output", "x.pfm", "--verbose", "--version",
                         "--", "-odd-name.pov"),
                   0);
  assert_int_equal(o.params.width, 5);
  assert_int_equal(o.params.height, 7);
  assert_int_equal(o.params.antialias, 1);
  assert_int_equal(o.params.aa_depth, 2);
  assert_int_equal(o.threads, 4);
  assert_int_equal(o.n_include_paths, 2);
  assert_string_equal(o.output, "x.pfm");
  assert_string_equal(o.input, "-odd-name.pov");
  assert_int_equal(o.verbose, 1);
  assert_int_equal(o.version, 1);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "--antialias=0.05", "--quiet", "--help",
                         "--input=a.pov", "--no-jitter"),
                   0);
  assert_true(o.params.aa_threshold == 0.05);
  assert_int_equal(o.params.jitter, 0);
  assert_int_equal(o.quiet, 1);
  assert_int_equal(o.help, 1);
  assert_string_equal(o.input, "a.pov");
  zr__cli_free(&o);
}

static void test_cli_options_ini_style(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "Width=99", "height=33", "Antialias=on",
                         "Antialias_Threshold=0.25", "Jitter=off",
                         "Library_Path=lib", "Work_Threads=2",
                         "Input_File_Name=s.pov", "Output_File_Type=P"),
                   0);
  assert_int_equal(o.params.width, 99);
  assert_int_equal(o.params.height, 33);
  assert_int_equal(o.params.antialias, 1);
  assert_true(o.params.aa_threshold == 0.25);
  assert_int_equal(o.params.jitter, 0);
  assert_string_equal(o.include_paths[0], "lib");
  assert_int_equal(o.threads, 2);
  assert_string_equal(o.input, "s.pov");
  assert_int_equal(o.format, ZR_FORMAT_PPM);
  zr__cli_free(&o);
}

static void test_cli_options_ini_file(void **state) {
  (void)state;
  char path[] = "/tmp/zr_test_cli_XXXXXX.ini";
  int fd = mkstemps(path, 4);
  assert_true(fd >= 0);
  FILE *f = fdopen(fd, "w");
  fputs("; render settings\n"
        "Width = 64   ; comment\n"
        "\n"
        "+H48 +A0.2\n"
        "Input_File_Name=box.pov\n"
        "[other]\n"
        "Width=1\n",
        f);
  fclose(f);
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, path, "+W65"), 0);
  /* Later options win; the [other] section is not read. */
  assert_int_equal(o.params.width, 65);
  assert_int_equal(o.params.height, 48);
  assert_int_equal(o.params.antialias, 1);
  assert_string_equal(o.input, "box.pov");
  zr__cli_free(&o);

  f = fopen(path, "w");
  fputs("Width=64\nHeight=tall\n", f);
  fclose(f);
  char want[600];
  snprintf(want, sizeof want,
           "zrcube: %s:2: 'Height=tall': the height must be a whole number "
           "from 1 to 65535",
           path);
  assert_int_equal(PARSE(&o, err, path), -1);
  assert_string_equal(err, want);
  zr__cli_free(&o);
  unlink(path);
  EXPECT_ERROR("zrcube: cannot open INI file '/nonexistent/x.ini': No such "
               "file or directory",
               "/nonexistent/x.ini");
}

static void test_cli_options_bad_values(void **state) {
  (void)state;
  EXPECT_ERROR("zrcube: '+Wabc': the width must be a whole number from 1 "
               "to 65535", "+Wabc");
  EXPECT_ERROR("zrcube: '+W0': the width must be a whole number from 1 "
               "to 65535", "+W0");
  EXPECT_ERROR("zrcube: '+W-5': the width must be a whole number from 1 "
               "to 65535", "+W-5");
  EXPECT_ERROR("zrcube: '+W12px': the width must be a whole number from 1 "
               "to 65535", "+W12px");
  EXPECT_ERROR("zrcube: '+H70000': the height must be a whole number from "
               "1 to 65535", "+H70000");
  EXPECT_ERROR("zrcube: '--height=x': the height must be a whole number "
               "from 1 to 65535", "--height", "x");
  EXPECT_ERROR("zrcube: 'Width=abc': the width must be a whole number from "
               "1 to 65535", "Width=abc");
  EXPECT_ERROR("zrcube: '+W' needs a width, as in +W640", "+W");
  EXPECT_ERROR("zrcube: '+O' needs a file name, as in +Oimage.png", "+O");
  EXPECT_ERROR("zrcube: '+WT0': the number of threads must be a whole "
               "number from 1 to 512", "+WT0");
  EXPECT_ERROR("zrcube: '+R10': the antialiasing depth must be a whole "
               "number from 1 to 9", "+R10");
  EXPECT_ERROR("zrcube: '+A-1': the antialiasing threshold must be a "
               "number from 0 up", "+A-1");
  EXPECT_ERROR("zrcube: '+Anan': the antialiasing threshold must be a "
               "number from 0 up", "+Anan");
  EXPECT_ERROR("zrcube: '+Jx': the jitter amount must be a number", "+Jx");
  EXPECT_ERROR("zrcube: 'Antialias=maybe': expected on or off",
               "Antialias=maybe");
  EXPECT_ERROR("zrcube: '--width' needs a value", "--width");
  EXPECT_ERROR("zrcube: '--verbose=1': --verbose takes no value",
               "--verbose=1");
}

static void test_cli_options_png_level(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "s.pov"), 0);
  assert_int_equal(o.png_level, ZR_DEFAULT_PNG_LEVEL);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "s.pov", "--png-level=9"), 0);
  assert_int_equal(o.png_level, 9);
  zr__cli_free(&o);
  EXPECT_ERROR("zrcube: '--png-level=10': --png-level must be 0 to 9",
               "--png-level=10");
  EXPECT_ERROR("zrcube: '--png-level=x': --png-level must be 0 to 9",
               "--png-level=x");
}

static void test_cli_options_unknown_and_unsupported(void **state) {
  (void)state;
  EXPECT_ERROR("zrcube: unknown option '+Z1' (try 'zrcube --help')", "+Z1");
  EXPECT_ERROR("zrcube: unknown option '--bogus' (try 'zrcube --help')",
               "--bogus=3");
  EXPECT_ERROR("zrcube: unknown option 'Bogus_Key' (try 'zrcube "
               "--help')", "Bogus_Key=on");
  EXPECT_ERROR("zrcube: unknown option '+Vx' (try 'zrcube --help')", "+Vx");
  EXPECT_ERROR("zrcube: '+FS': system-specific output is not supported "
               "(use N for PNG, J for JPEG, T or C for Targa, B for BMP, H "
               "for HDR, E for OpenEXR, P for PPM, or an output name "
               "ending in .pfm)", "+FS");
  EXPECT_ERROR("zrcube: '+FX': unknown output file type 'X' (use N for "
               "PNG, J for JPEG, T or C for Targa, B for BMP, H for HDR, E "
               "for OpenEXR or P for PPM)", "+FX");
  EXPECT_ERROR("zrcube: '+FH16': HDR files hold floats; they take no bits "
               "per colour", "+FH16");
  EXPECT_ERROR("zrcube: '+FT16': only PNG files take 16 bits per colour",
               "+FT16");
  EXPECT_ERROR("zrcube: '+FJx': bits per colour must be a whole number",
               "+FJx");
  EXPECT_ERROR("zrcube: 'Compression=x': the JPEG quality must be a whole "
               "number, as in Compression=90", "Compression=x");
  EXPECT_ERROR("zrcube: '+FN12': only 8 and 16 bits per colour are "
               "supported", "+FN12");
  EXPECT_ERROR("zrcube: '+FP16': PPM files are written with 8 bits per "
               "colour", "+FP16");
  EXPECT_ERROR("zrcube: '+AM3': the sampling method must be 1 or 2",
               "+AM3");
  EXPECT_ERROR("zrcube: '+AG2.2': the antialiasing gamma (+AG) is not "
               "supported", "+AG2.2");
  EXPECT_ERROR("zrcube: more than one scene file: 'a.pov' and 'b.pov'",
               "a.pov", "b.pov");
}

/* Resolves the output name of a parse that must succeed. */
static int output_of(const char **words, char **path, zr_image_format *fmt,
                     char *err) {
  zr_cli_options o;
  assert_int_equal(parse_words(&o, err, words), 0);
  int rc = zr__cli_output_path(&o, path, fmt, err, 512);
  zr__cli_free(&o);
  return rc;
}

#define OUTPUT(path, fmt, err, ...)                                        \
  output_of((const char *[]){__VA_ARGS__, NULL}, (path), (fmt), (err))

static void test_cli_options_output_names(void **state) {
  (void)state;
  char *path;
  zr_image_format fmt;
  char err[512];
  assert_int_equal(OUTPUT(&path, &fmt, err, "dir/sub/scene.pov"), 0);
  assert_string_equal(path, "scene.png"); /* in the current directory */
  assert_int_equal(fmt, ZR_FORMAT_PNG8);
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "scene", "+FP"), 0);
  assert_string_equal(path, "scene.ppm");
  assert_int_equal(fmt, ZR_FORMAT_PPM);
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "a.b/scene.pov", "+Oout/"), 0);
  assert_string_equal(path, "out/scene.png");
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Oimage"), 0);
  assert_string_equal(path, "image.png");
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Oimage.PFM"), 0);
  assert_string_equal(path, "image.PFM");
  assert_int_equal(fmt, ZR_FORMAT_PFM);
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Oimg.png", "+FN16"),
                   0);
  assert_int_equal(fmt, ZR_FORMAT_PNG16);
  free(path);
  /* An existing directory without the slash. */
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+O/tmp"), 0);
  assert_string_equal(path, "/tmp/s.png");
  free(path);

  /* POV-Ray's rule: the extension is appended in the folder named
     (issue 10: this wrote ./abc.png over the user's file). */
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Ooutdir/abc"), 0);
  assert_string_equal(path, "outdir/abc.png");
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+O/x/y/abc", "+FP"),
                   0);
  assert_string_equal(path, "/x/y/abc.ppm");
  free(path);
  /* Devices are refused by name, not renamed next to. */
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+O/dev/full"), -1);
  assert_string_equal(err, "zrcube: cannot write the image to '/dev/full': "
                           "it is a character device, not a regular file "
                           "or a directory");
  assert_null(path);

  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Oimage.gif"), -1);
  assert_string_equal(err, "zrcube: cannot write 'image.gif': the output "
                           "name must end in .png, .jpg, .tga, .bmp, .hdr, "
                           ".exr, .ppm or .pfm (or give the type with +F)");
  assert_null(path);
  /* Issue 12's types: the extension they add, and the JPEG quality. */
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+FJ90"), 0);
  assert_string_equal(path, "s.jpg");
  assert_int_equal(fmt, ZR_FORMAT_JPEG);
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+FB"), 0);
  assert_string_equal(path, "s.bmp");
  assert_int_equal(fmt, ZR_FORMAT_BMP);
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Oimage.bmp"), 0);
  assert_int_equal(fmt, ZR_FORMAT_BMP);
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+FC", "+Oa/b"), 0);
  assert_string_equal(path, "a/b.tga");
  assert_int_equal(fmt, ZR_FORMAT_TGA_RLE);
  free(path);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Opic.hdr"), 0);
  assert_int_equal(fmt, ZR_FORMAT_HDR);
  free(path);
  if (zr_image_format_supported(ZR_FORMAT_EXR)) {
    assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+FE"), 0);
    assert_string_equal(path, "s.exr");
    free(path);
  }
  assert_int_equal(OUTPUT(&path, &fmt, err, "+W4"), -1);
  assert_string_equal(err, "zrcube: no scene file given (try 'zrcube "
                           "--help')");
}

static void test_cli_options_never_overwrite_scene(void **state) {
  (void)state;
  char dir[] = "/tmp/zr_test_cli_XXXXXX";
  assert_non_null(mkdtemp(dir));
  char scene[64], other_spelling[64];
  snprintf(scene, sizeof scene, "%s/s.png", dir);
  snprintf(other_spelling, sizeof other_spelling, "%s/./s.png", dir);
  FILE *f = fopen(scene, "w");
  fputs("sphere { 0, 1 }\n", f);
  fclose(f);
  char *path;
  zr_image_format fmt;
  char err[512], want[600];
  snprintf(want, sizeof want,
           "zrcube: refusing to overwrite the scene file '%s' with the "
           "image", scene);
  char out_opt[80];
  snprintf(out_opt, sizeof out_opt, "+O%s", other_spelling);
  assert_int_equal(OUTPUT(&path, &fmt, err, scene, out_opt), -1);
  assert_string_equal(err, want);
  /* The default name is the scene's own when it ends in .png here. */
  char *cwd = getcwd(NULL, 0);
  assert_int_equal(chdir(dir), 0);
  assert_int_equal(OUTPUT(&path, &fmt, err, "s.png"), -1);
  assert_string_equal(err, "zrcube: refusing to overwrite the scene file "
                           "'s.png' with the image");
  assert_int_equal(chdir(cwd), 0);
  free(cwd);
  unlink(scene);
  rmdir(dir);
}

/* The image size against the library's limit, with its numbers. */
static void test_cli_options_image_limit(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "s.pov", "+W16384", "+H8192"), 0);
  assert_int_equal(zr__cli_check_size(&o, err, sizeof err), 0);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "s.pov", "+W16384", "+H8193"), 0);
  assert_int_equal(zr__cli_check_size(&o, err, sizeof err), -1);
  assert_string_equal(err, "zrcube: an image of 16384x8193 is 134234112 "
                           "pixels, more than the limit of 134217728 "
                           "(2^27) pixels; make +W or +H smaller");
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "s.pov", "+W65535", "+H65535"), 0);
  assert_int_equal(zr__cli_check_size(&o, err, sizeof err), -1);
  zr__cli_free(&o);
}

/* --read-path, --write-path, --io-restrictions and their INI keys. */
static void test_cli_options_io_restrictions(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "s.pov"), 0);
  assert_int_equal(o.io_mode, ZR_IO_RESTRICTED);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "s.pov", "--read-path=a", "--read-path",
                         "b", "Write_Path=c", "--io-restrictions=read-only"),
                   0);
  assert_int_equal(o.n_read_paths, 2);
  assert_string_equal(o.read_paths[0], "a");
  assert_string_equal(o.read_paths[1], "b");
  assert_int_equal(o.n_write_paths, 1);
  assert_string_equal(o.write_paths[0], "c");
  assert_int_equal(o.io_mode, ZR_IO_READ_ONLY);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "s.pov", "IO_Restrictions=none",
                         "Read_Paths=d", "write_paths=e"), 0);
  assert_int_equal(o.io_mode, ZR_IO_NONE);
  assert_int_equal(o.n_read_paths, 1);
  assert_string_equal(o.read_paths[0], "d");
  assert_int_equal(o.n_write_paths, 1);
  assert_string_equal(o.write_paths[0], "e");
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "s.pov", "--io-restrictions=off",
                         "--io-restrictions=on"), 0);
  assert_int_equal(o.io_mode, ZR_IO_RESTRICTED);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "s.pov", "IO_Restrictions=Strict"), 0);
  assert_int_equal(o.io_mode, ZR_IO_STRICT);
  zr__cli_free(&o);
  EXPECT_ERROR("zrcube: '--io-restrictions=maybe': the I/O restrictions "
               "are 'restricted' (or 'on'), 'strict', 'read-only' or "
               "'none' (or 'off')", "s.pov", "--io-restrictions=maybe");
  EXPECT_ERROR("zrcube: '--read-path=' needs a directory", "s.pov",
               "--read-path=");
}

/* The clock of each frame, as povray 3.7.0 prints it with #debug for the
   same options (measured: bench-free, in the commit that added this). */
static void expect_frames(const char *const *words, size_t want_n,
                          const long *numbers, const double *clocks,
                          double delta, int final_frame, int digits) {
  zr_cli_options o;
  char err[512];
  assert_int_equal(parse_words(&o, err, words), 0);
  zr_cli_frame *f;
  size_t n;
  int d;
  assert_int_equal(zr__cli_frames(&o, &f, &n, &d, err, sizeof err), 0);
  assert_int_equal(n, want_n);
  assert_int_equal(d, digits);
  for (size_t i = 0; i < n; i++) {
    assert_int_equal(f[i].number, numbers[i]);
    /* Exact up to rounding of a few operations. */
    assert_true(fabs(f[i].clock.clock - clocks[i]) < 1e-9);
    assert_true(fabs(f[i].clock.clock_delta - delta) < 1e-9);
    assert_int_equal(f[i].clock.final_frame, final_frame);
    assert_int_equal(f[i].clock.clock_on, digits > 0 || clocks[i] != 0);
  }
  free(f);
  zr__cli_free(&o);
}

static void test_cli_options_animation(void **state) {
  (void)state;
  expect_frames((const char *[]){"+KFF3", NULL}, 3, (long[]){1, 2, 3},
                (double[]){0, 0.5, 1}, 0.5, 3, 1);
  /* Cyclic: final_frame reads 4 and the clock stops short of 1. */
  expect_frames((const char *[]){"+KFF3", "+KC", NULL}, 3,
                (long[]){1, 2, 3}, (double[]){0, 1.0 / 3, 2.0 / 3},
                1.0 / 3, 4, 1);
  expect_frames((const char *[]){"+KFF10", "+SF9", NULL}, 2,
                (long[]){9, 10}, (double[]){8.0 / 9, 1}, 1.0 / 9, 10, 2);
  expect_frames((const char *[]){"+KI2", "+KF4", "+KFF3", NULL}, 3,
                (long[]){1, 2, 3}, (double[]){2, 3, 4}, 1, 3, 1);
  expect_frames((const char *[]){"+KFF10", "+SF0.5", "+EF0.7", NULL}, 3,
                (long[]){5, 6, 7}, (double[]){4.0 / 9, 5.0 / 9, 6.0 / 9},
                1.0 / 9, 10, 2);
  expect_frames((const char *[]){"+KFF7", "+STP3", NULL}, 3,
                (long[]){1, 4, 7}, (double[]){0, 0.5, 1}, 1.0 / 6, 7, 1);
  expect_frames((const char *[]){"+KFF100", "+SF99", NULL}, 2,
                (long[]){99, 100}, (double[]){98.0 / 99, 1}, 1.0 / 99, 100,
                3);
  expect_frames((const char *[]){"Initial_Frame=0", "Final_Frame=2", NULL},
                3, (long[]){0, 1, 2}, (double[]){0, 0.5, 1}, 0.5, 2, 1);
  /* A still with +K: clock_on, no frame number. */
  expect_frames((const char *[]){"+K0.5", NULL}, 1, (long[]){0},
                (double[]){0.5}, 0, 0, 0);
  /* The clock ignores +K in an animation. */
  expect_frames((const char *[]){"+KFF3", "Clock=0.7", NULL}, 3,
                (long[]){1, 2, 3}, (double[]){0, 0.5, 1}, 0.5, 3, 1);

  char *name = zr__cli_frame_name("out.png", 5, 2);
  assert_string_equal(name, "out05.png");
  free(name);
  name = zr__cli_frame_name("dir.v2/out", 7, 3);
  assert_string_equal(name, "dir.v2/out007");
  free(name);

  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, "+KFF3", "+SF5"), 0);
  zr_cli_frame *f;
  size_t n;
  int d;
  assert_int_equal(zr__cli_frames(&o, &f, &n, &d, err, sizeof err), -1);
  assert_string_equal(err, "zrcube: the subset starts at frame 5, after "
                           "the final frame 3");
  zr__cli_free(&o);
  EXPECT_ERROR("zrcube: '+KFFx': a frame number must be a whole number",
               "+KFFx");
  EXPECT_ERROR("zrcube: '+SF1.5': the subset frame must be a whole number "
               "from 1, or a fraction from 0.0 to 1.0", "+SF1.5");
}

static void test_cli_options_window(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  int r0, r1, c0, c1;
  /* Measured with povray 3.7.0 on a 10x10 image: both render rows 3 to
     5 (1-based), and +SC0.25 +EC0.55 columns 3 to 5. */
  assert_int_equal(PARSE(&o, err, "+W10", "+H10", "+SR0.25", "+ER0.55",
                         "+SC0.25", "+EC0.55"), 0);
  assert_int_equal(zr__cli_window(&o, &r0, &r1, &c0, &c1, err, sizeof err),
                   0);
  assert_int_equal(r0, 2);
  assert_int_equal(r1, 5);
  assert_int_equal(c0, 2);
  assert_int_equal(c1, 5);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "+W10", "+H10", "Start_Row=3",
                         "End_Row=5"), 0);
  assert_int_equal(zr__cli_window(&o, &r0, &r1, &c0, &c1, err, sizeof err),
                   0);
  assert_int_equal(r0, 2);
  assert_int_equal(r1, 5);
  assert_int_equal(c0, 0);
  assert_int_equal(c1, 10);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "+W10", "+H10", "+SR11"), 0);
  assert_int_equal(zr__cli_window(&o, &r0, &r1, &c0, &c1, err, sizeof err),
                   -1);
  assert_string_equal(err, "zrcube: the partial render starts outside the "
                           "10x10 image (+SR/+SC are 1-based, or fractions "
                           "below 1)");
  zr__cli_free(&o);
}

static void test_cli_options_prefixes_and_more(void **state) {
  (void)state;
  zr_cli_options o;
  char err[512];
  /* +HI is the header include, not +H; +WT and +WL are not +W. */
  assert_int_equal(PARSE(&o, err, "+HIhead.inc", "+H90", "+WT2", "+WL5",
                         "+W120", "+MV3.5", "Declare=RAD=0",
                         "--declare=Big=1e3", "+C", "+O-", "-GW",
                         "+GSstats.txt", "+KC", "+UL", "+UD"), 0);
  assert_string_equal(o.header_include, "head.inc");
  assert_int_equal(o.params.height, 90);
  assert_int_equal(o.params.width, 120);
  assert_int_equal(o.threads, 2);
  assert_true(o.lang_version == 3.5);
  assert_int_equal(o.n_declares, 2);
  assert_string_equal(o.declare_names[0], "RAD");
  assert_true(o.declare_values[0] == 0);
  assert_string_equal(o.declare_names[1], "Big");
  assert_true(o.declare_values[1] == 1000);
  assert_int_equal(o.continue_trace, 1);
  assert_int_equal(o.to_stdout, 1);
  assert_int_equal(o.stream_console[ZR_CLI_STREAM_WARNING], 0);
  assert_int_equal(o.stream_console[ZR_CLI_STREAM_STATISTICS], 1);
  assert_string_equal(o.stream_file[ZR_CLI_STREAM_STATISTICS], "stats.txt");
  assert_int_equal(o.cyclic, 1);
  /* +UL (speed only) is read silently, +UD named in a warning. */
  assert_int_equal(o.n_notes, 1);
  assert_string_equal(o.notes[0], "'+UD': ignored: zrcube does not "
                                  "dither");
  zr__cli_free(&o);
  /* JPEG quality: Compression= only, clipped to 0..100; the digits of
     +FJ are bits per colour, which povray ignores for JPEG (measured). */
  assert_int_equal(PARSE(&o, err, "+FJ90", "Compression=150"), 0);
  assert_int_equal(o.jpeg_quality, 100);
  assert_int_equal(o.n_notes, 1);
  assert_string_equal(o.notes[0], "'+FJ90': ignored: JPEG files take no "
                                  "bits per colour (set the JPEG quality "
                                  "with Compression=N)");
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "+FJ", "Compression=-4"), 0);
  assert_int_equal(o.jpeg_quality, 0);
  assert_int_equal(o.n_notes, 0);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "+FJ", "Compression=40"), 0);
  assert_int_equal(o.jpeg_quality, 40);
  zr__cli_free(&o);
  /* +UA and Output_Alpha: the renderer's alpha. */
  assert_int_equal(PARSE(&o, err, "+UA"), 0);
  assert_int_equal(o.params.alpha, 1);
  assert_int_equal(o.n_notes, 0);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "+UA", "Output_Alpha=off"), 0);
  assert_int_equal(o.params.alpha, 0);
  zr__cli_free(&o);
  assert_int_equal(PARSE(&o, err, "+GA", "All_File=on"), 0);
  assert_string_equal(o.stream_file[ZR_CLI_STREAM_DEBUG], "ALLTEXT.OUT");
  zr__cli_free(&o);
  EXPECT_ERROR("zrcube: 'Declare=1x=2': expected Declare=IDENTIFIER=FLOAT, "
               "as in Declare=MyValue=24", "Declare=1x=2");
  EXPECT_ERROR("zrcube: 'Declare=X=abc': expected Declare=IDENTIFIER=FLOAT, "
               "as in Declare=MyValue=24", "Declare=X=abc");
}

/* Sections: "file.ini[label]" reads only that section (user's guide
   2.2.8.2), labels ignore case and blanks; unknown keys in a file are
   named in a warning with file:line; a name alone is another INI. */
static void test_cli_options_ini_sections(void **state) {
  (void)state;
  char dir[] = "/tmp/zr_ini_XXXXXX";
  assert_non_null(mkdtemp(dir));
  char path[256], other[256], arg[300];
  snprintf(path, sizeof path, "%s/res.ini", dir);
  snprintf(other, sizeof other, "%s/more.ini", dir);
  FILE *f = fopen(path, "w");
  fputs("+W120 +H100\n[Low]\n+W80 +H60\n[Really High]\n"
        "Width=\"800\"\nNo_Such_Key=1\n", f);
  fclose(f);
  f = fopen(other, "w");
  fputs("Height=77\n", f);
  fclose(f);
  zr_cli_options o;
  char err[512];
  assert_int_equal(PARSE(&o, err, path), 0);
  assert_int_equal(o.params.width, 120);
  zr__cli_free(&o);
  snprintf(arg, sizeof arg, "%s[low]", path);
  assert_int_equal(PARSE(&o, err, arg), 0);
  assert_int_equal(o.params.width, 80);
  assert_int_equal(o.params.height, 60);
  zr__cli_free(&o);
  snprintf(arg, sizeof arg, "%s[ really high ]", path);
  assert_int_equal(PARSE(&o, err, arg), 0);
  assert_int_equal(o.params.width, 800);
  assert_int_equal(o.n_notes, 1);
  char want[600];
  snprintf(want, sizeof want, "%s:6: 'No_Such_Key=1': unknown key, ignored",
           path);
  assert_string_equal(o.notes[0], want);
  zr__cli_free(&o);
  snprintf(arg, sizeof arg, "%s[Nope]", path);
  assert_int_equal(PARSE(&o, err, arg), -1);
  snprintf(want, sizeof want, "zrcube: INI file '%s' has no section [Nope]",
           path);
  assert_string_equal(err, want);
  zr__cli_free(&o);
  /* A name alone on a line: another INI file, .ini assumed. */
  f = fopen(path, "w");
  fprintf(f, "%s/more\n", dir);
  fclose(f);
  assert_int_equal(PARSE(&o, err, path), 0);
  assert_int_equal(o.params.height, 77);
  zr__cli_free(&o);
  unlink(path);
  unlink(other);
  rmdir(dir);
}

/* Every INI file POV-Ray 3.7 ships reads without an error (skipped
   without them); its keys are read or named in a warning. */
/* The default povray.ini's Output_File_Type (Debian's says N8) yields to
   an output name whose extension names a type; +F on the command line
   still wins over the extension. */
static void test_cli_options_default_ini_format(void **state) {
  (void)state;
  char path[] = "/tmp/zr_test_povini_XXXXXX.ini";
  int fd = mkstemps(path, 4);
  assert_true(fd >= 0);
  FILE *f = fdopen(fd, "w");
  fputs("Output_File_Type=N8\n", f);
  fclose(f);
  const char *old = getenv("POVINI");
  char *saved = old ? strdup(old) : NULL;
  setenv("POVINI", path, 1);
  const char *cases[][3] = {
      /* +O name, +F or NULL, the expected type as a string */
      {"+Oa.pfm", NULL, "pfm"},
      {"+Oa.hdr", NULL, "hdr"},
      {"+Oa", NULL, "png"},
      {"+Oa.pfm", "+FN", "png"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
    zr_cli_options o;
    char err[512];
    char *argv[] = {"zrcube", "s.pov", (char *)cases[i][0],
                    (char *)cases[i][1], NULL};
    zr_render_params defaults;
    zr_render_params_init(&defaults);
    zr__cli_init(&o, &defaults);
    assert_int_equal(zr__cli_read_povray_ini(&o, err, sizeof err), 0);
    assert_int_equal(o.ini_format, ZR_FORMAT_PNG8);
    assert_int_equal(o.format, ZR_FORMAT_AUTO);
    int argc = cases[i][1] ? 4 : 3;
    assert_int_equal(zr__cli_parse(&o, argc, argv, err, sizeof err), 0);
    char *out;
    zr_image_format fmt;
    assert_int_equal(zr__cli_output_path(&o, &out, &fmt, err, sizeof err), 0);
    zr_image_format want = !strcmp(cases[i][2], "pfm")   ? ZR_FORMAT_PFM
                           : !strcmp(cases[i][2], "hdr") ? ZR_FORMAT_HDR
                                                         : ZR_FORMAT_PNG8;
    assert_int_equal(fmt, want);
    free(out);
    zr__cli_free(&o);
  }
  if (saved) {
    setenv("POVINI", saved, 1);
    free(saved);
  } else {
    unsetenv("POVINI");
  }
  unlink(path);
}

static void test_cli_options_stock_ini(void **state) {
  (void)state;
  static const char *const names[] = {
      "allanim", "allstill", "low", "pngflc", "pngfli", "povray",
      "quickres", "res120", "res1k", "res320", "res640", "res800",
      "slow", "tgaflc", "tgafli", "zipflc", "zipfli"};
  const char *dir = "/usr/share/povray-3.7/ini";
  struct stat st;
  if (stat(dir, &st) != 0)
    skip();
  for (size_t i = 0; i < sizeof names / sizeof *names; i++) {
    char path[256], lib[300];
    snprintf(path, sizeof path, "%s/%s.ini", dir, names[i]);
    snprintf(lib, sizeof lib, "+L%s", dir);
    zr_cli_options o;
    char err[512];
    int rc = PARSE(&o, err, lib, path);
    if (rc != 0 && strstr(err, "Targa output is not supported")) {
      /* TGA output comes with another change; the message must point
         at the line. */
      assert_non_null(strstr(err, ".ini:"));
    } else {
      if (rc != 0)
        print_error("%s: %s\n", names[i], err);
      assert_int_equal(rc, 0);
    }
    zr__cli_free(&o);
  }
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_cli_options_image_limit),
      cmocka_unit_test(test_cli_options_io_restrictions),
      cmocka_unit_test(test_cli_options_defaults),
      cmocka_unit_test(test_cli_options_povray_switches),
      cmocka_unit_test(test_cli_options_switches_turn_off),
      cmocka_unit_test(test_cli_options_long_options),
      cmocka_unit_test(test_cli_options_ini_style),
      cmocka_unit_test(test_cli_options_ini_file),
      cmocka_unit_test(test_cli_options_png_level),
      cmocka_unit_test(test_cli_options_bad_values),
      cmocka_unit_test(test_cli_options_unknown_and_unsupported),
      cmocka_unit_test(test_cli_options_output_names),
      cmocka_unit_test(test_cli_options_never_overwrite_scene),
      cmocka_unit_test(test_cli_options_animation),
      cmocka_unit_test(test_cli_options_window),
      cmocka_unit_test(test_cli_options_prefixes_and_more),
      cmocka_unit_test(test_cli_options_ini_sections),
      cmocka_unit_test(test_cli_options_stock_ini),
      cmocka_unit_test(test_cli_options_default_ini_format),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
