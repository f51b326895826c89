/*
 * options.h - the zrcube command line, parsed into plain data.
 *
 * Parsing is kept apart from main() so that the unit test can feed it
 * argument vectors and check every message; it prints nothing and opens
 * no file except INI files named on the command line.
 */
#ifndef ZR_BIN_OPTIONS_H
#define ZR_BIN_OPTIONS_H

#include <stddef.h>

#include "zrcube.h"

/* Limits: POV-Ray caps Work_Threads at 512 and Antialias_Depth at 9; the
   image side is kept below 65536 so pixel numbers fit in 32 bits. */
#define ZR_CLI_MAX_SIDE 65535
#define ZR_CLI_MAX_THREADS 512
#define ZR_CLI_MAX_AA_DEPTH 9

/* The text streams of POV-Ray's +G options, in this order. */
enum {
  ZR_CLI_STREAM_DEBUG,
  ZR_CLI_STREAM_FATAL,
  ZR_CLI_STREAM_RENDER,
  ZR_CLI_STREAM_STATISTICS,
  ZR_CLI_STREAM_WARNING,
  ZR_CLI_STREAMS
};

typedef struct zr_cli_options {
  char *input;            /* scene file, NULL until given */
  char *output;           /* +O as given, NULL for the default name */
  zr_image_format format; /* from +F, ZR_FORMAT_AUTO when not given */
  /* Output_File_Type from the default povray.ini: used only when the
     output name's extension names no type (AUTO: none given). */
  zr_image_format ini_format;
  int jpeg_quality;       /* +FJn: 0 .. 100 (0 and 1: 85), 0 if not given */
  double file_gamma;      /* File_Gamma: 0 sRGB (default), else a gamma */
  int write_output;       /* 0 after -F */
  char **include_paths;   /* +L, in the order given, duplicates dropped */
  size_t n_include_paths;
  zr_render_params params; /* the caller fills it with defaults first */
  int threads;            /* +WT; 0 means one per processor */
  int verbose;            /* statistics after the render */
  int quiet;              /* no progress, no warnings */
  int help;
  int version;
  int parse_only;         /* --parse-only: report what the scene holds */
  unsigned long long loop_limit; /* --max-work (--max-loop-iterations);
                                    0: none */
  int memory_limit_given;        /* --memory-limit was given */
  unsigned long long memory_limit; /* its bytes; 0: none */
  unsigned long long file_limit; /* --max-file-size; 0: none */
  int png_level;                 /* --png-level, zlib's 0 to 9 */
  zr_accel accel;                /* --accel */
  /* Radiosity (issue 4): any radiosity option turns it on. */
  int radiosity;          /* solve (or load) a solution, render with it */
  zr_radiosity_params rad; /* the solver's settings */
  /* Which of bf_eps, area_eps, visibility_rays, max_iterations,
     residual and bounces the command line set (ZR_CLI_RAD_* bits): those override
     the scene's radiosity block, the others come from it. */
  unsigned rad_given;
  int rad_stats;          /* --radiosity-stats: key=value lines */
  char *rad_save;         /* --radiosity-save=FILE, NULL when not given */
  char *rad_load;         /* --radiosity-load=FILE, NULL when not given */
  char *rad_mesh;         /* --radiosity-mesh=FILE, NULL when not given */
  /* I/O restrictions (zrcube(1), "I/O restrictions"). */
  zr_io_restrictions io_mode; /* --io-restrictions, default restricted */
  char **read_paths;      /* --read-path, as given */
  size_t n_read_paths;
  char **write_paths;     /* --write-path, as given */
  size_t n_write_paths;
  /* Global illumination: --gi (ZR_GI_AUTO unless given), +Q / Quality
     (9 when not given; 8 and below turn radiosity off), --no-radiosity
     and Radiosity=off (gi = ZR_GI_OFF), the cache's files. */
  zr_gi_method gi;
  int quality;
  char *gi_save;          /* --gi-save=FILE */
  char *gi_load;          /* --gi-load=FILE */
  /* Animation (reference 3.2.1): +K, +KFI, +KFF, +KI, +KF, +KC, +SF,
     +EF, +STP and their INI keys; zr__cli_frames() turns them into the
     frames to render. */
  int clock_given;        /* +K / Clock= */
  double clock;
  int initial_frame_given, final_frame_given;
  long initial_frame;     /* default 1 */
  long final_frame;       /* default 1 */
  double initial_clock;   /* default 0 */
  double final_clock;     /* default 1 */
  int cyclic;             /* +KC */
  double subset_start;    /* +SF as given; < 0 when not given */
  double subset_end;      /* +EF as given; < 0 when not given */
  long frame_step;        /* +STP, default 1 */
  int frames_per_rank;    /* --frames-per-rank: -1 auto, 0 no, 1 yes */
  /* Partial renders (3.2.2.3): as given, a fraction when below 1, a
     1-based pixel number otherwise; negative when not given. */
  double start_row, end_row, start_col, end_col;
  int continue_trace;     /* +C */
  double state_interval;  /* --state-interval seconds, default 10 */
  int to_stdout;          /* +O- */
  /* Declare=NAME=VALUE, in order. */
  char **declare_names;
  double *declare_values;
  size_t n_declares;
  double lang_version;    /* +MV / Version=; 0 when not given */
  /* Text streams (3.2.6): debug, fatal, render, statistics, warning:
     shown on the console (1, the default) or not, and copied to a file
     (NULL: none). */
  int stream_console[ZR_CLI_STREAMS];
  char *stream_file[ZR_CLI_STREAMS];
  char *header_include;   /* +HI / Include_Header= */
  /* INI keys zrcube reads and does not act on, each warned about once
     (file:line: key: why) by the caller after parsing. */
  char **notes;
  size_t n_notes;
  int ini_read;           /* how many INI files were read */
  int spp;                /* --spp: path tracer's samples a pixel (64) */
  uint32_t path_seed;     /* --path-seed (0) */
} zr_cli_options;

/* One frame of an animation: its number and the scene's clock values. */
typedef struct zr_cli_frame {
  long number;
  zr_parse_options clock;
} zr_cli_frame;

/*
 * The frames the options ask for (POV-Ray's internal animation loop,
 * reference 3.2.1.2-3.2.1.4), in order, into a malloc'ed *frames; *n is
 * 1 for a still image (frame_number 0, clock from +K or 0).  *digits is
 * the width of the frame number in output names (the digits of the
 * final frame), 0 for a still.  Returns -1 with a message in err for a
 * subset outside the animation.
 */
int zr__cli_frames(const zr_cli_options *o, zr_cli_frame **frames,
                   size_t *n, int *digits, char *err, size_t err_size);

/* The image name of frame number (digits wide) for the still's name
   path: "out.png" -> "out05.png"; malloc'ed. */
char *zr__cli_frame_name(const char *path, long number, int digits);

/*
 * The render window of a partial render (+SR +ER +SC +EC) in pixels,
 * 0-based, end exclusive; the whole image when none was given.  Returns
 * -1 with a message in err when the window is empty or outside.
 */
int zr__cli_window(const zr_cli_options *o, int *row0, int *row1,
                   int *col0, int *col1, char *err, size_t err_size);

/*
 * Reads the first povray.ini POV-Ray for Unix would read, before the
 * command line: $POVINI, else ./povray.ini, else
 * $HOME/.povray/3.7/povray.ini, else the system's
 * (/etc/povray/3.7/povray.ini), else $HOME/.povrayrc.  POVINI set but
 * empty reads none (a zrcube extension, used by the tests).  Returns 0,
 * or -1 with a message in err.
 */
int zr__cli_read_povray_ini(zr_cli_options *o, char *err, size_t err_size);

/*
 * Prepares o: zeroes it and copies the render defaults in, with the
 * radiosity defaults of zr_radiosity_params_init() (emission from the
 * sides it gets away from: zrcube(1), --one-sided-emission).  Parsing may
 * then run over several sources (command line, INI files) in order.
 */
void zr__cli_init(zr_cli_options *o, const zr_render_params *defaults);

enum {
  ZR_CLI_RAD_BF_EPS = 1u << 0,
  ZR_CLI_RAD_AREA_EPS = 1u << 1,
  ZR_CLI_RAD_VIS_RAYS = 1u << 2,
  ZR_CLI_RAD_MAX_ITERATIONS = 1u << 3,
  ZR_CLI_RAD_RESIDUAL = 1u << 4,
  ZR_CLI_RAD_BOUNCES = 1u << 5
};

/*
 * The solver's settings for scene: the command line's (o->rad), except
 * that what it did not set comes from the scene's global_settings {
 * radiosity { } } block (zr_radiosity_params_init), brightness always.
 */
void zr__cli_radiosity_params(const zr_cli_options *o, const zr_scene *scene,
                              zr_radiosity_params *out);
void zr__cli_free(zr_cli_options *o);

/* The model the options ask for before the scene is seen: --gi, or
   off after --no-radiosity, Radiosity=off or +Q8 and below, or
   hierarchical after a hierarchical solver option (--radiosity,
   --bf-eps ...); else ZR_GI_AUTO. */
zr_gi_method zr__cli_gi_asked(const zr_cli_options *o);

/*
 * Parses argv[1 .. argc-1].  On failure returns -1 and writes a one-line
 * message, "zrcube: ...", without a newline, into err.
 */
int zr__cli_parse(zr_cli_options *o, int argc, char **argv, char *err,
                  size_t err_size);

/*
 * Checks what must hold after all options are read (a scene was named)
 * and works out the image file: the default name (the scene's base name
 * with the format's extension, in the current directory), a directory
 * given as +O, an extension for a name without one.  Refuses a name that
 * is the scene file itself.  *path is malloc'ed.  Returns -1 with a
 * message in err on failure.
 */
int zr__cli_output_path(const zr_cli_options *o, char **path,
                        zr_image_format *format, char *err,
                        size_t err_size);

/*
 * Checks the image size against the library's limit,
 * ZR_IMAGE_MAX_PIXELS (2^27) pixels in all, before any parsing: -1 with
 * a message giving the numbers in err when it is too large.
 */
int zr__cli_check_size(const zr_cli_options *o, char *err, size_t err_size);

/* The --help text. */
const char *zr__cli_usage(void);

#endif /* ZR_BIN_OPTIONS_H */
