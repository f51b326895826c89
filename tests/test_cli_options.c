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
static int parse_words(zr_cli_options *o, char *err, const char **words) {
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
  EXPECT_ERROR("zrcube: cannot open '/nonexistent/x.ini': No such file or "
               "directory",
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

static void test_cli_options_unknown_and_unsupported(void **state) {
  (void)state;
  EXPECT_ERROR("zrcube: unknown option '+UL' (try 'zrcube --help')", "+UL");
  EXPECT_ERROR("zrcube: unknown option '--bogus' (try 'zrcube --help')",
               "--bogus=3");
  EXPECT_ERROR("zrcube: unknown option 'Light_Buffer' (try 'zrcube "
               "--help')", "Light_Buffer=on");
  EXPECT_ERROR("zrcube: unknown option '+Vx' (try 'zrcube --help')", "+Vx");
  EXPECT_ERROR("zrcube: '+FT': Targa output is not supported (use N for "
               "PNG, P for PPM, or an output name ending in .pfm)", "+FT");
  EXPECT_ERROR("zrcube: '+FX': unknown output file type 'X' (use N for PNG "
               "or P for PPM)", "+FX");
  EXPECT_ERROR("zrcube: '+FN12': only 8 and 16 bits per colour are "
               "supported", "+FN12");
  EXPECT_ERROR("zrcube: '+FP16': PPM files are written with 8 bits per "
               "colour", "+FP16");
  EXPECT_ERROR("zrcube: '+AM3': the sampling method must be 1 or 2",
               "+AM3");
  EXPECT_ERROR("zrcube: '+AG2.2': the antialiasing gamma (+AG) is not "
               "supported", "+AG2.2");
  EXPECT_ERROR("zrcube: '+O-': writing the image to standard output is not "
               "supported", "+O-");
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

  assert_int_equal(OUTPUT(&path, &fmt, err, "s.pov", "+Oimage.tga"), -1);
  assert_string_equal(err, "zrcube: cannot write 'image.tga': the output "
                           "name must end in .png, .ppm or .pfm (or give "
                           "the type with +FN or +FP)");
  assert_null(path);
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
  EXPECT_ERROR("zrcube: '--io-restrictions=maybe': the I/O restrictions "
               "are 'restricted' (or 'on'), 'read-only' or 'none' (or "
               "'off')", "s.pov", "--io-restrictions=maybe");
  EXPECT_ERROR("zrcube: '--read-path=' needs a directory", "s.pov",
               "--read-path=");
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
      cmocka_unit_test(test_cli_options_bad_values),
      cmocka_unit_test(test_cli_options_unknown_and_unsupported),
      cmocka_unit_test(test_cli_options_output_names),
      cmocka_unit_test(test_cli_options_never_overwrite_scene),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
