/*
 * zrcube.c - the command line: render a POV-Ray scene, alone or under
 * mpirun.
 *
 * The program is meant to replace `povray` in a user's command: the same
 * switches (options.c follows POV-Ray 3.7's reference, section 3.2), the
 * same default output name, diagnostics on stderr.  Its own work is the
 * order of events across ranks, after ARCHITECTURE.md ("Parallelism"):
 *   1. every rank reads the command line (so all agree on the options);
 *   2. rank 0 parses the scene with a reader that records the files it
 *      reads, and broadcasts them with its parse status (lib/par);
 *   3. if rank 0's parse failed every rank stops: only rank 0 has printed
 *      the library's diagnostics, once; otherwise every other rank parses
 *      the same bytes from memory;
 *   4. the model of global illumination is chosen (zr_gi_choose); for
 *      the irradiance cache every rank runs the same deterministic
 *      pretrace; for hierarchical radiosity the ranks solve one
 *      radiosity solution together, as a team (zrcube.h, lib/par's
 *      zr__par_team): each computes its share of the transfer factors,
 *      visibility and refinement plans, they exchange them, and every
 *      rank ends with the same bytes as one rank alone; or every rank
 *      loads it from --radiosity-load's file, which every rank must then
 *      see; rank 0 saves it and prints its statistics;
 *   5. all ranks render their interleaved rows with threads, rank 0
 *      gathers the picture and writes it.
 * Every step that may fail on one rank is followed by an agreement on the
 * status, so all ranks leave with the same exit status and none waits in
 * a collective that another has abandoned.
 *
 * Exit status: 0 success, 1 the scene or image failed, 2 the command line
 * was wrong.
 */
#include "config.h"

#include <errno.h>
#include <stdarg.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "options.h"
#include "state.h"
#include "par/bundle.h"
#include "par/par.h"
#include "par/writer.h"
#include "zrcube.h"

enum { EXIT_SCENE = 1, EXIT_USAGE = 2 };

/*
 * Ctrl-C and SIGTERM in a run without mpirun: the handler cancels the
 * context (zr_context_cancel is safe in a handler), the phase running
 * stops within a row or a sweep, everything is freed and nothing is
 * written, and main raises the signal again so the exit status still
 * says what ended the run.  Under mpirun the launcher owns the signals.
 */
static zr_context *volatile signal_ctx;
static volatile sig_atomic_t signal_caught;

static void on_signal(int sig) {
  signal_caught = sig;
  if (signal_ctx)
    zr_context_cancel(signal_ctx, 1);
}

static void catch_signals(zr_context *ctx) {
  signal_ctx = ctx;
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  int sigs[] = {SIGINT, SIGTERM};
  for (int i = 0; i < 2; i++) {
    struct sigaction old;
    /* A signal the shell set to be ignored (a job started with &) stays
       ignored, as it would without the handler. */
    if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
      sigaction(sigs[i], &sa, NULL);
  }
}

/*
 * The progress line (rank 0): on a terminal one line that each phase
 * (parse, radiosity or pretrace, render) overwrites with its percent,
 * elapsed time and what is left, as POV-Ray's "Rendered N of M pixels";
 * with +V and stderr not a terminal, a plain line at every tenth of a
 * phase instead; otherwise nothing.
 */
typedef struct progress_state {
  int mode;          /* 0 none, 1 terminal line, 2 plain lines (+V) */
  int line_open;     /* the terminal line holds text */
  int phase;         /* the phase shown, -1 before the first */
  double phase_start;
  double last_print;
  int last_tenth;    /* mode 2: the last tenth printed */
} progress_state;

/* What the diagnostics callback needs: who prints, and what it printed;
   and POV-Ray's text streams (+GD +GF +GR +GS +GW, reference 3.2.7):
   each shown on the console or not, and copied to a file or not. */
typedef struct diag_state {
  int rank;
  int quiet;
  int silent; /* a rank other than 0 tries a parse: nothing is printed */
  unsigned errors_printed;
  const int *console;  /* ZR_CLI_STREAMS flags */
  FILE **files;        /* ZR_CLI_STREAMS files, NULL: none */
  int last_stream;     /* where a note goes: with its message */
  progress_state *progress; /* a message first clears its line */
  /* The first error the console did not show (-GF or -GA): a failed
     run still tells why (main), as povray -GA still prints its fatal
     error. */
  char hidden_error[2048];
  int capturing; /* the first error's text is still coming */
} diag_state;

/* Clears the terminal's progress line so a message starts clean. */
static void clear_progress_line(progress_state *p) {
  if (p && p->line_open) {
    fputs("\r\033[K", stderr);
    p->line_open = 0;
  }
}


/* Text of one stream: to the console unless turned off, and to the
   stream's file.  Warnings also keep --quiet's meaning. */
static void emit(diag_state *st, int stream, const char *text) {
  st->last_stream = stream;
  int console = !st->console || st->console[stream];
  if (stream == ZR_CLI_STREAM_WARNING && st->quiet)
    console = 0;
  if (console) {
    clear_progress_line(st->progress);
    fputs(text, stderr);
  } else if (stream == ZR_CLI_STREAM_FATAL && st->capturing) {
    size_t used = strlen(st->hidden_error);
    snprintf(st->hidden_error + used, sizeof st->hidden_error - used, "%s",
             text);
  }
  if (st->files && st->files[stream]) {
    fputs(text, st->files[stream]);
    fflush(st->files[stream]);
  }
}

static void say(diag_state *st, int stream, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static void say(diag_state *st, int stream, const char *fmt, ...) {
  char text[2048];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(text, sizeof text, fmt, ap);
  va_end(ap);
  emit(st, stream, text);
}

/*
 * Rank 0 prints everything the library says (warnings and #debug output
 * unless --quiet).  The other ranks parse what rank 0 already parsed
 * without error, so they stay silent except for an error, which would
 * mean the ranks disagree and must not go unseen.
 */
static void print_diag(const zr_diag *d, void *user) {
  diag_state *st = user;
  if (st->rank != 0 && st->silent)
    return;
  if (st->rank != 0) {
    if (d->level == ZR_DIAG_ERROR) {
      fprintf(stderr, "zrcube: rank %d: %s", st->rank, d->text);
      st->errors_printed++;
    }
    return;
  }
  if (d->level == ZR_DIAG_ERROR)
    st->capturing = st->errors_printed == 0;
  int stream = d->level == ZR_DIAG_ERROR     ? ZR_CLI_STREAM_FATAL
               : d->level == ZR_DIAG_WARNING ? ZR_CLI_STREAM_WARNING
               : d->level == ZR_DIAG_DEBUG   ? ZR_CLI_STREAM_DEBUG
                                             : st->last_stream;
  emit(st, stream, d->text);
  if (d->level == ZR_DIAG_ERROR)
    st->errors_printed++;
}

static const char *const phase_names[] = {"parse", "radiosity", "pretrace",
                                           "render"};
static const char *const phase_units[] = {"tokens", "rounds", "pixels",
                                          "rows"};

/* A duration as POV-Ray's line shows it: seconds, or minutes and
   seconds past a minute. */
static const char *duration(double s, char *buf, size_t size) {
  if (s < 60)
    snprintf(buf, size, "%.1f s", s);
  else
    snprintf(buf, size, "%d min %02d s", (int)(s / 60), (int)s % 60);
  return buf;
}

static void show_progress(progress_state *p, int phase, uint64_t done,
                          uint64_t total) {
  if (p->mode == 0)
    return;
  double now = zr__par_now();
  if (phase != p->phase) {
    p->phase = phase;
    p->phase_start = now;
    p->last_print = 0;
    p->last_tenth = -1;
  }
  int finished = total && done >= total;
  /* Ten updates a second are plenty for the eye. */
  if (p->mode == 1 && !finished && now - p->last_print < 0.1)
    return;
  int tenth = total ? (int)(10 * done / total) : 0;
  if (p->mode == 2 && (!total || tenth == p->last_tenth))
    return;
  p->last_print = now;
  p->last_tenth = tenth;
  double elapsed = now - p->phase_start;
  char line[160], a[32], b[32];
  if (!total) {
    snprintf(line, sizeof line, "zrcube: %s: %llu %s, %s", phase_names[phase],
             (unsigned long long)done, phase_units[phase],
             duration(elapsed, a, sizeof a));
  } else {
    int percent = (int)(100 * done / total);
    int n = snprintf(line, sizeof line, "zrcube: %s: %llu of %llu %s (%d%%), "
                     "%s", phase_names[phase], (unsigned long long)done,
                     (unsigned long long)total, phase_units[phase], percent,
                     duration(elapsed, a, sizeof a));
    /* What is left, once a second of work says how fast it goes. */
    if (done > 0 && !finished && elapsed >= 1.0 && n > 0 &&
        (size_t)n < sizeof line)
      snprintf(line + n, sizeof line - (size_t)n, ", about %s left",
               duration(elapsed * (double)(total - done) / (double)done, b,
                        sizeof b));
  }
  if (p->mode == 1) {
    fprintf(stderr, "\r%s\033[K", line);
    p->line_open = 1;
  } else {
    fprintf(stderr, "%s\n", line);
  }
  fflush(stderr);
}

/* The library's progress (parse, radiosity, pretrace); never cancels. */
static int on_progress(const zr_progress *pr, void *user) {
  show_progress(user, (int)pr->phase, pr->done, pr->total);
  return 0;
}

/* lib/par's rows of this rank. */
static void on_rows(size_t done, size_t total, void *user) {
  if (done > total)
    done = total; /* the count of rows to do is an estimate (lib/par) */
  show_progress(user, ZR_PHASE_RENDER, done, total);
}

/*
 * POV-Ray accepts a scene name without its .pov; so does zrcube when the
 * name as given does not exist.  Returns 0, or -1 after printing why the
 * scene cannot be opened.
 */
static int find_scene(zr_cli_options *o) {
  struct stat st;
  if (stat(o->input, &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      fprintf(stderr, "zrcube: cannot read scene file '%s': it is a "
                      "directory\n", o->input);
      return -1;
    }
    return 0;
  }
  int err = errno;
  size_t n = strlen(o->input) + 5;
  char *with_pov = malloc(n);
  if (with_pov) {
    snprintf(with_pov, n, "%s.pov", o->input);
    if (stat(with_pov, &st) == 0 && !S_ISDIR(st.st_mode)) {
      free(o->input);
      o->input = with_pov;
      return 0;
    }
    free(with_pov);
  }
  fprintf(stderr, "zrcube: cannot open scene file '%s': %s\n", o->input,
          strerror(err));
  return -1;
}

/*
 * Fails early, before a long parse and render, when a file the run will
 * write (the image, a radiosity save or mesh) could not be written: the
 * library writes a new file beside the target and renames it over the
 * target (lib/core/iopolicy.c), so this creates and removes such a file
 * in the same folder, and refuses a target that exists and is not a
 * writable regular file (a symbolic link is judged by its file).
 * Returns 0, or -1 after printing why.  Nothing the user has is touched.
 */
static int check_writable(const char *what, const char *path) {
  struct stat st;
  char *target = NULL;
  if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode))
    target = realpath(path, NULL); /* NULL: a link to nothing yet */
  if (!target)
    target = strdup(path);
  if (!target) {
    fprintf(stderr, "zrcube: out of memory\n");
    return -1;
  }
  int rc = 0;
  if (stat(target, &st) == 0) {
    if (!S_ISREG(st.st_mode)) {
      fprintf(stderr, "zrcube: cannot write the %s to '%s': it is not a "
                      "regular file\n", what, path);
      rc = -1;
    } else if (access(target, W_OK) != 0) {
      fprintf(stderr, "zrcube: cannot write the %s to '%s': %s\n", what,
              path, strerror(errno));
      rc = -1;
    }
  }
  size_t n = strlen(target) + 64;
  char *probe = rc == 0 ? malloc(n) : NULL;
  if (probe) {
    snprintf(probe, n, "%s.%ld.probe.tmp", target, (long)getpid());
    int fd = open(probe, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0600);
    if (fd < 0) {
      const char *slash = strrchr(target, '/');
      fprintf(stderr, "zrcube: cannot write the %s to '%s': cannot create "
                      "a file in %s%.*s%s: %s\n", what, path,
              slash ? "'" : "the working directory",
              slash ? (int)(slash - target + (slash == target)) : 0,
              target, slash ? "'" : "", strerror(errno));
      rc = -1;
    } else {
      close(fd);
      unlink(probe);
    }
  } else if (rc == 0) {
    fprintf(stderr, "zrcube: out of memory\n");
    rc = -1;
  }
  free(probe);
  free(target);
  return rc;
}

/* Every file the run will write, checked before the scene is read. */
static int check_outputs(const zr_cli_options *o, const char *image) {
  if (o->parse_only)
    return 0;
  if (o->write_output && check_writable("image", image))
    return -1;
  if (o->rad_save && check_writable("radiosity solution", o->rad_save))
    return -1;
  if (o->rad_mesh && check_writable("radiosity mesh", o->rad_mesh))
    return -1;
  return 0;
}

typedef struct run {
  zr_par *par;   /* the ranks rendering this frame: world, or solo */
  zr_par *world; /* every rank of the job */
  zr_par *solo;  /* this rank alone, for whole frames per rank */
  int rank;
  zr_cli_options opts;
  char *still_path;  /* the image name before frame numbers */
  char *output_path; /* this frame's image, NULL for +O- */
  char *state_path;  /* this frame's state file, NULL: none kept */
  zr_cli_frame *frames;
  size_t n_frames;
  int digits;        /* of frame numbers in names; 0 for a still */
  const zr_cli_frame *frame;
  int row0, row1, col0, col1; /* the window of a partial render */
  uint64_t fingerprint;       /* of the scene's files and the options */
  double last_state_write;
  /* Rank 0: where the radiosity solution goes beside the state file,
     written just before the state file first is (band_done); NULL when
     it is written, not wanted or resumed from. */
  char *state_rad;
  double state_write_seconds; /* how long the last one took */
  int state_failed;           /* a state write failed (warned once) */
  FILE *stream_files[ZR_CLI_STREAMS];
  zr_image_format format;
  int threads;
  zr_context *ctx;
  diag_state diag;
  zr_bundle bundle;
  /* A rank alone keeps no copy of the files it read (a second 15 MB for
     a big mesh): it hashes them as they come, into files_hash, and
     keeps each one's size and hash to check a second reading. */
  struct file_digest {
    char *path;
    size_t size;
    uint64_t hash;
  } *digests;
  size_t n_digests;
  uint64_t files_hash;
  zr_scene *scene;
  zr_image *image;
  zr_radiosity *rad;
  zr_gi_cache *gi;
  zr_path *path; /* --gi=path */
  zr_team team; /* all ranks, solving and pretracing together */
  zr_gi_method gi_method;
  double gi_seconds;
  double parse_seconds;
  double radiosity_seconds;
  double write_seconds;
  /* This rank's CPU seconds in each phase (-v, bench/scale.sh). */
  double parse_cpu, gi_cpu, radiosity_cpu, render_cpu;
  zr_par_render render;
  progress_state progress;
} run;

/* Steps 1: the command line on every rank.  Returns an exit status or -1
   to go on. */
static int read_command_line(run *r, int argc, char **argv) {
  zr_render_params defaults;
  zr_render_params_init(&defaults);
  zr__cli_init(&r->opts, &defaults);
  r->progress.phase = -1;
  char err[1024];
  /* POV-Ray for Unix reads its povray.ini before the command line. */
  int rc = zr__cli_read_povray_ini(&r->opts, err, sizeof err);
  if (rc == 0)
    rc = zr__cli_parse(&r->opts, argc, argv, err, sizeof err);
  if (rc == 0)
    rc = zr__cli_frames(&r->opts, &r->frames, &r->n_frames, &r->digits,
                        err, sizeof err);
  if (rc == 0)
    rc = zr__cli_window(&r->opts, &r->row0, &r->row1, &r->col0, &r->col1,
                        err, sizeof err);
  zr_status agreed = zr__par_agree(r->par, rc == 0 ? ZR_OK : ZR_EINVAL);
  if (rc != 0 && r->rank == 0)
    fprintf(stderr, "%s\n", err);
  else if (agreed != ZR_OK && r->rank == 0)
    fprintf(stderr, "zrcube: another rank could not read the command "
                    "line (an INI file missing on its host?)\n");
  if (agreed != ZR_OK)
    return EXIT_USAGE;
  if (r->opts.help || r->opts.version) {
    if (r->rank == 0 && r->opts.help) {
      fputs(zr__cli_usage(), stdout);
    } else if (r->rank == 0) {
      char mpi[256];
      zr__par_mpi_version(mpi, sizeof mpi);
      printf("zrcube %s (libzrcube %s, %s)\n", ZR_VERSION_STRING,
             zr_version(), mpi);
    }
    return EXIT_SUCCESS;
  }
  if (r->rank == 0)
    for (size_t i = 0; i < r->opts.n_notes; i++)
      if (!r->opts.quiet)
        fprintf(stderr, "zrcube: warning: %s\n", r->opts.notes[i]);
  /* The scene and the image name matter on rank 0 only. */
  int usage = 0, unusable = 0;
  if (r->rank == 0) {
    if (r->opts.to_stdout && r->opts.continue_trace) {
      fprintf(stderr, "zrcube: +C continues a render written to a file; "
                      "it cannot be used with +O-\n");
      usage = 1;
    } else if (r->opts.continue_trace && !r->opts.write_output) {
      fprintf(stderr, "zrcube: +C continues a render written to a file; "
                      "it cannot be used with -F (reference 3.2.2.5)\n");
      usage = 1;
    } else if (!r->opts.input) {
      fprintf(stderr, "zrcube: no scene file given (try 'zrcube "
                      "--help')\n");
      usage = 1;
    } else if (find_scene(&r->opts) < 0) {
      unusable = 1;
    } else if (!r->opts.to_stdout &&
               zr__cli_output_path(&r->opts, &r->still_path, &r->format,
                                   err, sizeof err) < 0) {
      fprintf(stderr, "%s\n", err);
      usage = 1;
    } else if (!r->opts.parse_only &&
               zr__cli_check_size(&r->opts, err, sizeof err) < 0) {
      fprintf(stderr, "%s\n", err);
      usage = 1;
    } else if (!r->opts.to_stdout &&
               check_outputs(&r->opts, r->still_path)) {
      unusable = 1;
    }
    if (r->opts.to_stdout)
      r->format = r->opts.format == ZR_FORMAT_AUTO ? ZR_FORMAT_PNG8
                                                   : r->opts.format;
  }
  zr_status s = zr__par_agree(r->par, usage      ? ZR_EINVAL
                                      : unusable ? ZR_ENOTFOUND
                                                 : ZR_OK);
  if (s == ZR_EINVAL)
    return EXIT_USAGE;
  if (s != ZR_OK)
    return EXIT_SCENE;
  /* Rank 0 may have found "scene" as "scene.pov": the other ranks must
     ask their bundle for the name rank 0 parsed. */
  /* Whole frames may be rendered on other ranks, which then need the
     image name too. */
  if (zr__par_share_string(r->par, &r->opts.input) != ZR_OK ||
      zr__par_share_string(r->par, &r->still_path) != ZR_OK) {
    if (r->rank == 0)
      fprintf(stderr, "zrcube: cannot send the scene name to the other "
                      "ranks\n");
    return EXIT_SCENE;
  }
  if (r->rank != 0 && r->still_path)
    r->format = r->opts.format != ZR_FORMAT_AUTO
                    ? r->opts.format
                    : zr_image_format_from_name(r->still_path);
  /* +UA with a format that holds no alpha: povray warns and writes the
     pixels it writes without +UA (measured with +FP), and so does this,
     on every rank alike. */
  zr_image_format written =
      !r->opts.to_stdout ? r->format
      : r->opts.format == ZR_FORMAT_AUTO ? ZR_FORMAT_PNG8 : r->opts.format;
  if (r->opts.params.alpha && written != ZR_FORMAT_PNG8 &&
      written != ZR_FORMAT_PNG16 && written != ZR_FORMAT_TGA &&
      written != ZR_FORMAT_TGA_RLE && written != ZR_FORMAT_BMP &&
      written != ZR_FORMAT_EXR && r->opts.write_output) {
    if (r->rank == 0)
      say(&r->diag, ZR_CLI_STREAM_WARNING, "zrcube: warning: +UA: this "
          "output format holds no alpha channel; the image is written "
          "without one (use PNG, Targa, BMP or OpenEXR)\n");
    r->opts.params.alpha = 0;
  }
  r->threads = zr__par_threads(r->par, r->opts.threads);
  /* mpirun binds each rank to one core unless told otherwise, and then
     extra threads only take turns on it. */
  int cpus = zr__par_cpus_allowed();
  if (r->rank == 0 && !r->opts.quiet && r->threads > cpus)
    fprintf(stderr, "zrcube: warning: %d threads per rank, but this rank "
                    "may only run on %d processor%s (for mpirun, try "
                    "--bind-to none)\n", r->threads, cpus,
            cpus == 1 ? "" : "s");
  return -1;
}

/*
 * The I/O restrictions of the command line.  The folders matter where
 * files are read, on rank 0 (the other ranks read rank 0's files from
 * memory), so only rank 0 stops on a folder that is not there; the
 * others add the folders they have, for the files #fopen writes.
 */
static zr_status add_folders(run *r, char **dirs, size_t n, int write) {
  for (size_t i = 0; i < n; i++) {
    zr_status s = write ? zr_context_add_write_path(r->ctx, dirs[i])
                        : zr_context_add_read_path(r->ctx, dirs[i]);
    if (s == ZR_OK || r->rank != 0)
      continue;
    fprintf(stderr, "zrcube: --%s-path '%s': %s\n",
            write ? "write" : "read", dirs[i],
            s == ZR_ENOTFOUND ? "no such directory"
            : s == ZR_EINVAL  ? "not a directory"
                              : zr_status_str(s));
    return s;
  }
  return ZR_OK;
}

static zr_status set_io_restrictions(run *r) {
  zr_status s = zr_context_set_io_restrictions(r->ctx, r->opts.io_mode);
  if (s == ZR_OK)
    s = add_folders(r, r->opts.read_paths, r->opts.n_read_paths, 0);
  if (s == ZR_OK)
    s = add_folders(r, r->opts.write_paths, r->opts.n_write_paths, 1);
  return s;
}

static zr_status make_context(run *r) {
  zr_status s = zr_context_new(&r->ctx);
  if (s != ZR_OK)
    return s;
  r->diag.rank = r->rank;
  r->diag.quiet = r->opts.quiet;
  r->diag.progress = &r->progress;
  zr_context_set_diag(r->ctx, print_diag, &r->diag);
  /* Progress on rank 0: a line on a terminal, plain lines with +V. */
  if (r->rank == 0 && !r->opts.quiet)
    r->progress.mode = isatty(2) ? 1 : r->opts.verbose ? 2 : 0;
  if (r->progress.mode)
    zr_context_set_progress(r->ctx, on_progress, &r->progress);
  /* The library's calls report through the context (the pretrace
     takes the render's parameters). */
  r->opts.params.context = r->ctx;
  /* Scenes read image_width and image_height while they are parsed. */
  zr_context_set_work_limit(r->ctx, r->opts.loop_limit);
  zr_context_set_file_limit(r->ctx, r->opts.file_limit);
  zr_context_set_png_level(r->ctx, r->opts.png_level);
  /* +WT: a large mesh's hierarchy is built by the rank's threads too. */
  zr_context_set_threads(r->ctx, r->threads);
  if (zr_context_set_accel(r->ctx, r->opts.accel) != ZR_OK) {
    if (r->rank == 0)
      fprintf(stderr, "zrcube: --accel=embree: this zrcube was built "
                      "without Embree (configure --with-embree)\n");
    return ZR_EUNSUPPORTED;
  }
  if (r->opts.memory_limit_given)
    zr_context_set_memory_limit(r->ctx, r->opts.memory_limit);
  s = zr_context_set_render_size(r->ctx, r->opts.params.width,
                                 r->opts.params.height);
  /* The frame's clock and +MV (zr_parse_options), Declare= floats. */
  if (s == ZR_OK)
    s = zr_context_set_parse_options(r->ctx, &r->frame->clock);
  if (s == ZR_OK && r->opts.header_include)
    s = zr_context_set_header_include(r->ctx, r->opts.header_include);
  for (size_t i = 0; i < r->opts.n_declares && s == ZR_OK; i++)
    s = zr_context_declare(r->ctx, r->opts.declare_names[i],
                           r->opts.declare_values[i]);
  for (size_t i = 0; i < r->opts.n_include_paths && s == ZR_OK; i++)
    s = zr_context_add_include_path(r->ctx, r->opts.include_paths[i]);
  /* POV-Ray's own include files come after the user's paths.  Every
     rank lists it, present on its host or not, so that all ranks search
     the same paths in the same order and ask the bundle for the same
     files as rank 0 asked the disk. */
  if (s == ZR_OK)
    s = zr_context_add_include_path(r->ctx, ZR_POVRAY_INCLUDE_DIR);
  if (s == ZR_OK)
    s = set_io_restrictions(r);
  if (s == ZR_OK && !zr__par_uses_mpi(r->par))
    catch_signals(r->ctx);
  return s;
}

/* One file into the fingerprint of the files read: its path, size and
   the hash of its bytes (hash), in the order first read. */
static uint64_t fold_file(uint64_t h, const char *path, size_t size,
                          uint64_t hash) {
  h = zr__state_hash(h, path, strlen(path) + 1);
  h = zr__state_hash(h, &size, sizeof size);
  return zr__state_hash(h, &hash, sizeof hash);
}

/* What digest_observer recorded of the file at path, or NULL. */
static const struct file_digest *find_digest(const run *r, const char *path) {
  for (size_t i = 0; i < r->n_digests; i++)
    if (strcmp(r->digests[i].path, path) == 0)
      return &r->digests[i];
  return NULL;
}

/* The read observer of every rank that reads the disk: files_hash
   takes each file as it comes; a file read again must be the same
   bytes, as the bundle's recorder checks. */
static zr_status digest_observer(const char *path, const char *bytes,
                                 size_t size, void *user) {
  run *r = user;
  uint64_t hash = zr__state_digest(bytes, size);
  const struct file_digest *seen = find_digest(r, path);
  if (seen)
    return seen->size == size && seen->hash == hash ? ZR_OK : ZR_EIO;
  struct file_digest *d =
      realloc(r->digests, (r->n_digests + 1) * sizeof *d);
  if (!d)
    return ZR_ENOMEM;
  r->digests = d;
  if (!(d[r->n_digests].path = strdup(path)))
    return ZR_ENOMEM;
  d[r->n_digests].size = size;
  d[r->n_digests++].hash = hash;
  r->files_hash = fold_file(r->files_hash, path, size, hash);
  return ZR_OK;
}

/* Rank 0 of several also keeps what it read, for ranks that could not
   read the same files themselves: small files as a copy, files of
   BUNDLE_DEFER_FROM bytes or more as their digest only (r->bundle's
   defer_from), to be read again if another rank needs them
   (fill_bundle).  Such ranks are rare (another host, a file rank 0
   wrote meanwhile), and the copy was every run's: 15 MB of fresh pages
   and a memcpy on rank 0 for bench/peers.sh's terrain, in the parse
   the other ranks then waited for at the mesh's shared build
   (bench/results/session18-2026-12-04.md). */
#define BUNDLE_DEFER_FROM ((size_t)1 << 20)

static zr_status root_observer(const char *path, const char *bytes,
                               size_t size, void *user) {
  run *r = user;
  zr_status s = zr__bundle_record_observer(path, bytes, size, &r->bundle);
  return s == ZR_OK ? digest_observer(path, bytes, size, user) : s;
}

/* zr__bundle_fill's check: the bytes read again are those parsed, by
   the size and digest digest_observer recorded. */
static zr_status same_as_parsed(const char *path, const char *bytes,
                                size_t size, void *user) {
  const struct file_digest *seen = find_digest(user, path);
  return seen && seen->size == size &&
                 seen->hash == zr__state_digest(bytes, size)
             ? ZR_OK
             : ZR_EIO;
}

/* Rank 0, before it sends its files: the deferred ones read again.  A
   file that changed on disk since rank 0 parsed it cannot be sent as
   parsed; the run stops with a message rather than let the ranks
   render two scenes. */
static zr_status fill_bundle(run *r) {
  const char *failed = NULL;
  zr_status s = zr__bundle_fill(&r->bundle, same_as_parsed, r, &failed);
  if (s != ZR_OK)
    fprintf(stderr, "zrcube: cannot send '%s' to the other ranks: %s\n",
            failed ? failed : "?",
            s == ZR_EIO ? "it changed on disk after rank 0 read it; "
                          "render again"
                        : zr_status_str(s));
  return s;
}

static void free_digests(run *r) {
  for (size_t i = 0; i < r->n_digests; i++)
    free(r->digests[i].path);
  free(r->digests);
  r->digests = NULL;
  r->n_digests = 0;
}

/*
 * Under mpirun every rank parses at once, each reading the files from
 * its own disk (a rank that waited for rank 0's parse and then parsed
 * its copy took 1.6 times one rank's time on bench/peers.sh's terrain):
 * then rank 0 tells its status, the fingerprint of the files it read
 * and their number, and a rank that read other bytes, or could not
 * read them (another host, a file rank 0 wrote meanwhile), or failed
 * where rank 0 did not, parses again from the files rank 0 sends, as
 * ARCHITECTURE.md's broadcast has it.  Only rank 0 prints what the
 * parse says; rank 0's failure is everyone's.
 */
static int same_files_as_root(run *r, zr_status local, zr_status *root) {
  char *text = NULL;
  if (r->rank == 0) {
    char buf[96];
    snprintf(buf, sizeof buf, "%d %llu %zu", (int)local,
             (unsigned long long)r->files_hash, r->n_digests);
    text = strdup(buf);
  }
  int root_status = ZR_EMPI;
  unsigned long long root_hash = 0;
  size_t root_files = 0;
  zr_status s = zr__par_share_string(r->par, &text);
  if (s != ZR_OK || !text ||
      sscanf(text, "%d %llu %zu", &root_status, &root_hash, &root_files) !=
          3)
    root_status = s != ZR_OK ? (int)s : ZR_EMPI;
  free(text);
  *root = (zr_status)root_status;
  return r->rank == 0 || (local == ZR_OK && root_hash == r->files_hash &&
                          root_files == r->n_digests);
}

/* Steps 2 and 3: the scene, parsed on every rank at once. */
static int read_scene(run *r) {
  zr_status local = make_context(r);
  int have_context = local == ZR_OK;
  zr_status root = local;
  int several = zr__par_size(r->par) > 1;
  zr__bundle_init(&r->bundle);
  r->bundle.max_file_size = r->opts.file_limit;
  r->bundle.defer_from = BUNDLE_DEFER_FROM;
  r->files_hash = ZR_STATE_HASH_START;
  zr__par_mark("parse start");
  double start = zr__par_now(), cpu = zr__par_cpu();
  /* Each rank builds a large mesh's hierarchy alone.  Sharing the
     build (zr_context_set_team, the ranks meeting at the mesh and
     trading their halves) paid when the parse was slower; now it costs
     more in meetings and copies than it saves: rank 0's parse of
     bench/peers.sh's terrain (130,050 triangles) under mpirun -n 2, 10
     interleaved pairs on the quiet machine, alone 0.0885-0.1071 s
     (median 0.100) against shared 0.0911-0.1281 s (0.108), and of a
     terrain of 522,242 triangles 0.306-0.460 s (0.335) against
     0.319-0.759 s (0.377) (bench/results/session18-2026-12-04.md).
     With no meeting in it, each rank's parse is its own: a rank that
     could not parse cannot leave the others waiting there. */
  if (have_context) {
    /* The library's own reader applies the I/O restrictions. */
    zr_context_set_read_observer(r->ctx,
                                 r->rank == 0 && several ? root_observer
                                                         : digest_observer,
                                 r);
    if (r->rank != 0) {
      /* Rank 0 writes the scene's #fopen files; the others say nothing
         unless they must parse again (below). */
      zr_context_set_scene_writes(r->ctx, 0);
      r->diag.silent = 1;
    }
    local = zr_scene_parse_file(r->ctx, r->opts.input, &r->scene);
    r->diag.silent = 0;
    if (r->rank == 0 && local != ZR_OK && r->diag.errors_printed == 0)
      fprintf(stderr, "zrcube: cannot read scene '%s': %s\n",
              r->opts.input, zr_status_str(local));
  }
  root = local;
  int from_bundle = 0;
  if (several) {
    int same = same_files_as_root(r, local, &root);
    if (root != ZR_OK)
      return EXIT_SCENE;
    zr_status agreed = zr__par_agree(r->par, same ? ZR_OK : ZR_EIO);
    if (agreed != ZR_OK && agreed != ZR_EIO)
      return EXIT_SCENE;
    if (agreed == ZR_EIO) {
      if (r->rank == 0 && root == ZR_OK) {
        zr_status filled = fill_bundle(r);
        if (filled != ZR_OK)
          root = filled; /* every rank learns it with the bundle */
      }
      zr_status s = zr__par_share_bundle(r->par, &r->bundle, &root);
      if (s != ZR_OK) {
        if (r->rank == 0)
          fprintf(stderr, "zrcube: cannot send the scene to the other "
                          "ranks: %s\n", zr_status_str(s));
        return EXIT_SCENE;
      }
      if (root != ZR_OK)
        return EXIT_SCENE;
      if (!same && have_context) {
        zr_scene_free(r->scene);
        r->scene = NULL;
        zr_context_set_read_observer(r->ctx, NULL, NULL);
        zr_context_set_reader(r->ctx, zr__bundle_serve_reader, &r->bundle);
        local = zr_scene_parse_file(r->ctx, r->opts.input, &r->scene);
        from_bundle = 1;
        if (local != ZR_OK && r->diag.errors_printed == 0)
          fprintf(stderr, "zrcube: rank %d: cannot read scene '%s': %s\n",
                  r->rank, r->opts.input, zr_status_str(local));
      }
    }
  } else if (root != ZR_OK) {
    return EXIT_SCENE;
  }
  r->parse_seconds = zr__par_now() - start;
  r->parse_cpu = zr__par_cpu() - cpu;
  zr__par_mark("parse end");
  if (zr__par_agree(r->par, local) != ZR_OK) {
    if (r->rank == 0)
      fprintf(stderr, "zrcube: the scene parsed here failed on another "
                      "rank\n");
    return EXIT_SCENE;
  }
  /* A fingerprint of what the pixels depend on, for the state file: the
     files rank 0 read and the options that change pixels. */
  uint64_t h = r->files_hash;
  if (from_bundle) {
    h = ZR_STATE_HASH_START;
    for (size_t i = 0; i < r->bundle.count; i++) {
      const zr_bundle_file *f = &r->bundle.files[i];
      h = fold_file(h, f->path, f->size,
                    zr__state_digest(f->bytes, f->size));
    }
  }
  free_digests(r);
  const zr_render_params *p = &r->opts.params;
  double reals[] = {p->aa_threshold, p->jitter_amount,
                    r->frame->clock.clock, r->frame->clock.clock_delta,
                    r->frame->clock.initial_clock,
                    r->frame->clock.final_clock, r->frame->clock.version};
  int ints[] = {p->width, p->height, p->antialias, p->aa_depth, p->jitter,
                p->aa_method, p->quality,
                p->radiosity_only, r->opts.quality, (int)r->opts.gi,
                (int)zr__cli_gi_asked(&r->opts), r->opts.radiosity,
                (int)r->opts.rad_given, r->frame->clock.frame_number,
                r->frame->clock.clock_on, r->frame->clock.initial_frame,
                r->frame->clock.final_frame, r->row0, r->row1, r->col0,
                r->col1};
  h = zr__state_hash(h, reals, sizeof reals);
  h = zr__state_hash(h, ints, sizeof ints);
  if (p->alpha) /* +UA: another pixel layout (4 floats) */
    h = zr__state_hash(h, "alpha", 6);
  for (size_t i = 0; i < r->opts.n_declares; i++) {
    h = zr__state_hash(h, r->opts.declare_names[i],
                       strlen(r->opts.declare_names[i]) + 1);
    h = zr__state_hash(h, &r->opts.declare_values[i], sizeof(double));
  }
  r->fingerprint = h;
  /* The files are in the scene now; the copies are no longer needed. */
  zr__bundle_free(&r->bundle);
  return -1;
}

/* --radiosity-stats: key=value words on stderr, one group a line, for
   scripts (bench/radiosity.sh reads elements, links, iterations and
   residual). */
static void print_radiosity_stats(const run *r) {
  zr_radiosity_stats st;
  zr_radiosity_get_stats(r->rad, &st);
  fprintf(stderr,
          "zrcube: radiosity: surfaces=%zu nodes=%zu elements=%zu "
          "links=%zu vertices=%zu\n"
          "zrcube: radiosity: rounds=%d iterations=%d residual=%.3g "
          "visibility_rays=%llu seconds=%.3f\n"
          "zrcube: radiosity: emitted=%.6g absorbed=%.6g "
          "closure_mean=%.6f closure_min=%.6f closure_max=%.6f "
          "lights=%.6g\n",
          st.surfaces, st.nodes, st.elements, st.links, st.vertices,
          st.refine_rounds, st.iterations, st.residual,
          (unsigned long long)st.visibility_rays, r->radiosity_seconds,
          st.emitted_power, st.absorbed_power, st.closure_mean,
          st.closure_min, st.closure_max, st.light_power);
}

/* Writes an image of the scene as POV-Ray would: the scene's working
   gamma undone, then the file gamma (File_Gamma, sRGB by default), or
   none at all in a legacy scene (zr_scene_file_gamma). */
static zr_status write_image_in(zr_context *ctx, run *r,
                                const zr_image *image, const char *path,
                                zr_image_format format) {
  zr_image_encoding enc;
  zr_scene_image_encoding(r->scene, format, &enc);
  if (enc.file_gamma <= 0.0)
    enc.file_gamma = r->opts.file_gamma;
  enc.quality = r->opts.jpeg_quality;
  return zr_image_save(ctx, image, path, &enc);
}

static zr_status write_image(run *r, const zr_image *image,
                             const char *path, zr_image_format format) {
  return write_image_in(r->ctx, r, image, path, format);
}

/* --radiosity-mesh=FILE: the solution's mesh at the render's size, on
   rank 0 (it depends only on the solution, the same on every rank). */
static zr_status write_radiosity_mesh(run *r) {
  const zr_render_params *p = &r->opts.params;
  zr_image *mesh = NULL;
  unsigned before = r->diag.errors_printed;
  zr_status s = zr_image_new(p->width, p->height, &mesh);
  if (s == ZR_OK)
    s = zr_radiosity_mesh_image(r->rad, p, zr_image_pixels(mesh));
  if (s == ZR_OK)
    s = write_image(r, mesh, r->opts.rad_mesh, ZR_FORMAT_AUTO);
  if (s != ZR_OK && r->diag.errors_printed == before)
    fprintf(stderr, "zrcube: cannot write the radiosity mesh to '%s': "
                    "%s\n", r->opts.rad_mesh, zr_status_str(s));
  zr_image_free(mesh);
  return s;
}

/* Step 4: the radiosity solution, on every rank. */
static int solve_radiosity(run *r) {
  zr_radiosity_params params;
  zr__cli_radiosity_params(&r->opts, r->scene, &params);
  params.threads = r->threads; /* +WT: the same solution for any count */
  /* The solution is saved beside the state file, so +C does not solve
     again (state.h: path + ".rad"). */
  char *state_rad = NULL;
  if (!r->opts.rad_load && r->state_path) {
    size_t n = strlen(r->state_path) + 5;
    state_rad = malloc(n);
    if (state_rad)
      snprintf(state_rad, n, "%s.rad", r->state_path);
  }
  const char *load = r->opts.rad_load;
  int resumed = 0;
  if (state_rad && r->opts.continue_trace) {
    struct stat st;
    int there = r->rank == 0 && stat(state_rad, &st) == 0 &&
                stat(r->state_path, &st) == 0;
    resumed = zr__par_agree(r->par, there ? ZR_EINVAL : ZR_OK) != ZR_OK;
    if (resumed)
      load = state_rad;
  }
  params.team = &r->team;      /* and for any number of ranks */
  double start = zr__par_now(), cpu = zr__par_cpu();
  zr_status s;
  if (load)
    s = zr_radiosity_load(r->ctx, r->scene, load, &r->rad);
  else
    s = zr_radiosity_solve(r->ctx, r->scene, &params, &r->rad);
  /* The solution is wanted beside the state file only once there is a
     state file to continue from: band_done writes it then.  A render
     done sooner (every render shorter than --state-interval) writes
     neither: saving cornell.pov's 64x64 solution (3.5 MB) took rank 0
     15 ms of CPU (best of 7, load 19) in a render of 0.8 s a rank on
     2 ranks, while the other rank waited for it
     (bench/results/rad-2026-12-03-s13.md). */
  free(r->state_rad);
  r->state_rad = NULL;
  if (r->rank == 0 && state_rad && !resumed && s == ZR_OK) {
    r->state_rad = state_rad;
    state_rad = NULL;
  }
  free(state_rad);
  r->radiosity_seconds = zr__par_now() - start;
  r->radiosity_cpu = zr__par_cpu() - cpu;
  if (s != ZR_OK && r->rank == 0 && !*zr_context_last_error(r->ctx))
    fprintf(stderr, "zrcube: radiosity failed: %s\n", zr_status_str(s));
  if (zr__par_agree(r->par, s) != ZR_OK) {
    if (s == ZR_OK && r->rank == 0)
      fprintf(stderr, "zrcube: the radiosity solution failed on another "
                      "rank\n");
    return EXIT_SCENE;
  }
  r->opts.params.radiosity = r->rad;
  s = ZR_OK;
  if (r->rank == 0) {
    if (r->opts.rad_stats)
      print_radiosity_stats(r);
    if (r->opts.rad_save) {
      unsigned before = r->diag.errors_printed;
      s = zr_radiosity_save(r->ctx, r->rad, r->opts.rad_save);
      if (s != ZR_OK && r->diag.errors_printed == before)
        fprintf(stderr, "zrcube: cannot save the radiosity solution to "
                        "'%s': %s\n", r->opts.rad_save, zr_status_str(s));
    }
    if (s == ZR_OK && r->opts.rad_mesh)
      s = write_radiosity_mesh(r);
  }
  return zr__par_agree(r->par, s) == ZR_OK ? -1 : EXIT_SCENE;
}

/*
 * Step 4 for the irradiance cache: every rank runs the same pretrace
 * (deterministic, lib/gi/cache.c), so every rank holds the same cache
 * and no records travel.  sky_only: the sky's light beside a
 * hierarchical solution.
 */
static int build_cache(run *r, int sky_only) {
  zr_gi_params gp;
  zr_gi_params_init(&gp, r->scene);
  gp.threads = r->threads;
  gp.team = &r->team;
  gp.sky_only = sky_only;
  const char *load = sky_only ? NULL
                     : r->opts.gi_load ? r->opts.gi_load : gp.load_file;
  const char *save = sky_only ? NULL
                     : r->opts.gi_save ? r->opts.gi_save : gp.save_file;
  /* The cache is saved beside the state file, so +C does not redo the
     pretrace (state.h: path + ".gi"). */
  char *state_gi = NULL;
  if (!sky_only && !load && r->state_path) {
    size_t n = strlen(r->state_path) + 4;
    state_gi = malloc(n);
    if (state_gi)
      snprintf(state_gi, n, "%s.gi", r->state_path);
  }
  int resumed = 0;
  if (state_gi && r->opts.continue_trace) {
    struct stat st;
    int there = r->rank == 0 && stat(state_gi, &st) == 0 &&
                stat(r->state_path, &st) == 0;
    resumed = zr__par_agree(r->par, there ? ZR_EINVAL : ZR_OK) != ZR_OK;
    if (resumed)
      load = state_gi;
  }
  double start = zr__par_now(), cpu = zr__par_cpu();
  zr_status s = load ? zr_gi_cache_load(r->ctx, r->scene, &gp, load, &r->gi)
                     : zr_gi_cache_new(r->ctx, r->scene, &gp, &r->gi);
  /* A loaded cache is used as it is (its render is the saved one's);
     the final pass gathers where it has no record. */
  if (s == ZR_OK && !load)
    s = zr_gi_cache_pretrace(r->gi, &r->opts.params);
  r->gi_seconds = zr__par_now() - start;
  r->gi_cpu = zr__par_cpu() - cpu;
  if (s != ZR_OK && r->rank == 0 && !*zr_context_last_error(r->ctx))
    fprintf(stderr, "zrcube: irradiance cache failed: %s\n",
            zr_status_str(s));
  if (zr__par_agree(r->par, s) != ZR_OK)
    return EXIT_SCENE;
  r->opts.params.gi_cache = r->gi;
  s = ZR_OK;
  if (r->rank == 0 && r->opts.verbose) {
    zr_gi_stats st;
    zr_gi_cache_get_stats(r->gi, &st);
    fprintf(stderr, "zrcube: irradiance cache%s: %zu records (%zu at "
            "the first bounce), %d pretrace passes, %llu sample rays, "
            "%.3f s\n", sky_only ? " (sky light)" : "", st.records,
            st.records_depth0, st.pretrace_passes,
            (unsigned long long)st.sample_rays, r->gi_seconds);
  }
  if (r->rank == 0 && save) {
    unsigned before = r->diag.errors_printed;
    s = zr_gi_cache_save(r->ctx, r->gi, save);
    if (s != ZR_OK && r->diag.errors_printed == before)
      fprintf(stderr, "zrcube: cannot save the irradiance cache to '%s': "
              "%s\n", save, zr_status_str(s));
  }
  if (r->rank == 0 && state_gi && !resumed && s == ZR_OK &&
      zr_gi_cache_save(r->ctx, r->gi, state_gi) != ZR_OK)
    say(&r->diag, ZR_CLI_STREAM_WARNING, "zrcube: warning: cannot save "
        "the irradiance cache beside the state file ('%s'); +C would "
        "compute it again\n", state_gi);
  free(state_gi);
  return zr__par_agree(r->par, s) == ZR_OK ? -1 : EXIT_SCENE;
}

/* Step 4 for the path-traced reference (lib/gi/path.c): every rank
   makes the same table of emitters; antialiasing is the tracer's own
   sampling of the pixel. */
static int set_up_path(run *r) {
  zr_path_params pp;
  zr_path_params_init(&pp);
  pp.seed = r->opts.path_seed;
  zr_status s = zr_path_new(r->rank == 0 ? r->ctx : NULL, r->scene, &pp,
                            &r->path);
  if (s != ZR_OK && r->rank == 0)
    fprintf(stderr, "zrcube: path tracer failed: %s\n", zr_status_str(s));
  if (zr__par_agree(r->par, s) != ZR_OK)
    return EXIT_SCENE;
  r->opts.params.path = r->path;
  if (r->opts.params.alpha && r->rank == 0)
    say(&r->diag, ZR_CLI_STREAM_WARNING, "zrcube: warning: +UA is not "
        "supported with the path tracer (--gi=path); the image is written "
        "without alpha\n");
  r->opts.params.alpha = 0;
  r->opts.params.path_samples = r->opts.spp;
  r->opts.params.path_first_sample = 0;
  r->opts.params.antialias = 0;
  if (r->rank == 0 && r->opts.verbose)
    fprintf(stderr, "zrcube: path tracer: %d samples a pixel, %zu "
            "emitting triangles sampled directly\n", r->opts.spp,
            zr_path_emitters(r->path));
  return -1;
}

/*
 * The path tracer's samples in rounds of 1, 1, 2, 4 ... (each as many
 * as all before it), each round's mean added into the image with its
 * weight, and the image written after every round but the last (which
 * the caller writes): a run stopped early leaves the last complete
 * estimate.  The rounds depend only on --spp, so the bytes do too.
 */
static zr_status render_path(run *r) {
  zr_render_params params = r->opts.params;
  const int total = params.path_samples;
  zr_image *round_image = NULL;
  double *sum = NULL;
  size_t n = (size_t)params.width * (size_t)params.height * 3;
  zr_status s = ZR_OK;
  if (r->rank == 0) {
    s = zr_image_new(params.width, params.height, &round_image);
    sum = s == ZR_OK ? calloc(n, sizeof *sum) : NULL;
    if (s == ZR_OK && !sum)
      s = ZR_ENOMEM;
  }
  if (zr__par_agree(r->par, s) != ZR_OK) {
    zr_image_free(round_image);
    free(sum);
    return ZR_ENOMEM;
  }
  zr_render_stats stats = {0};
  double seconds = 0.0;
  zr_par_render job = r->render;
  job.params = &params;
  job.image = round_image;
  for (int done = 0; done < total && s == ZR_OK;) {
    int k = done == 0 ? 1 : done;
    if (k > total - done)
      k = total - done;
    params.path_first_sample = done;
    params.path_samples = k;
    s = zr__par_render(r->par, &job);
    if (s != ZR_OK)
      break;
    zr_render_stats_add(&stats, &job.stats);
    seconds += job.render_seconds;
    done += k;
    if (r->rank != 0)
      continue;
    const float *round = zr_image_pixels_const(round_image);
    float *out = zr_image_pixels(r->image);
    for (size_t i = 0; i < n; i++) {
      sum[i] += (double)round[i] * k;
      out[i] = (float)(sum[i] / done);
    }
    if (done < total && r->opts.write_output &&
        write_image(r, r->image, r->output_path, r->format) != ZR_OK)
      fprintf(stderr, "zrcube: cannot write '%s' after %d samples\n",
              r->output_path, done);
  }
  r->render.stats = stats;
  r->render.render_seconds = seconds;
  zr_image_free(round_image);
  free(sum);
  return s;
}

/* Step 4: the model of global illumination (zr_gi_choose, zrcube(1)
   "Global illumination"), then what it needs before the render. */
static int set_up_gi(run *r) {
  zr_gi_method asked = zr__cli_gi_asked(&r->opts);
  char why[256];
  r->gi_method = zr_gi_choose(r->scene, asked, why, sizeof why);
  /* +V names the option that decided (zrcube(1), "Global
     illumination"), in zr__cli_gi_asked's order. */
  const char *option = NULL;
  char q[64];
  if (r->opts.gi == ZR_GI_OFF) {
    option = "--gi=off, --no-radiosity or Radiosity=off";
  } else if (r->opts.gi != ZR_GI_AUTO) {
    option = "--gi";
  } else if (r->opts.quality <= 8) {
    snprintf(q, sizeof q,
             "+Q%d: POV-Ray computes radiosity at quality 9 to 11",
             r->opts.quality);
    option = q;
  } else if (r->opts.rad_load) {
    option = "--radiosity-load names a saved solution";
  } else if (r->opts.radiosity) {
    option = "--radiosity or a hierarchical solver option";
  }
  if (r->rank == 0 && r->opts.verbose)
    fprintf(stderr, "zrcube: global illumination: %s (%s%s)\n",
            zr_gi_method_name(r->gi_method),
            option ? "" : "auto: ", option ? option : why);
  if (r->gi_method == ZR_GI_CACHE)
    return build_cache(r, 0);
  if (r->gi_method == ZR_GI_PATH)
    return set_up_path(r);
  if (r->gi_method != ZR_GI_HIERARCHICAL)
    return -1;
  int status = solve_radiosity(r);
  /* The solver carries no sky light: a sky-only cache adds it. */
  if (status < 0 && !r->opts.params.radiosity_only &&
      zr_gi_has_sky(r->scene))
    status = build_cache(r, 1);
  return status;
}

/* Rank 0, after each band: the state file, at most every
   --state-interval seconds (0: after every band), so an interrupted
   render (a kill -9 included) can continue with +C. */
static void band_done(const zr_par_progress *pr, void *user) {
  run *r = user;
  if (!r->state_path || r->state_failed)
    return;
  double now = zr__par_now();
  /* A big image's state takes a while to write: keep that under 5% of
     the render (unless asked for every band). */
  double gap = r->opts.state_interval;
  if (gap > 0 && gap < 20 * r->state_write_seconds)
    gap = 20 * r->state_write_seconds;
  if (now - r->last_state_write < gap)
    return;
  if (r->state_rad) {
    if (zr_radiosity_save(r->ctx, r->rad, r->state_rad) != ZR_OK)
      say(&r->diag, ZR_CLI_STREAM_WARNING, "zrcube: warning: cannot save "
          "the radiosity solution beside the state file ('%s'); +C would "
          "solve it again\n", r->state_rad);
    free(r->state_rad);
    r->state_rad = NULL;
  }
  int rc = zr__state_write(r->state_path, r->fingerprint,
                           r->opts.params.width, r->opts.params.height, pr);
  r->last_state_write = zr__par_now();
  r->state_write_seconds = r->last_state_write - now;
  if (rc != 0) {
    say(&r->diag, ZR_CLI_STREAM_WARNING, "zrcube: warning: cannot write "
        "the state file '%s' (+C will not be able to continue): %s\n",
        r->state_path, strerror(errno));
    r->state_failed = 1;
  }
}

/* +O-: the image in the chosen format on standard output, by way of a
   private temporary file (the library writes images to files). */
static zr_status write_to_stdout(run *r) {
  const char *dir = getenv("TMPDIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/zrcube-XXXXXX.%s",
           dir && *dir ? dir : "/tmp",
           r->format == ZR_FORMAT_PPM ? "ppm"
           : r->format == ZR_FORMAT_PFM ? "pfm" : "png");
  int suffix = (int)strlen(strrchr(path, '.'));
  int fd = mkstemps(path, suffix);
  if (fd < 0) {
    fprintf(stderr, "zrcube: cannot make a temporary file for +O-: %s\n",
            strerror(errno));
    return ZR_EIO;
  }
  close(fd);
  unsigned before = r->diag.errors_printed;
  zr_status s = write_image(r, r->image, path, r->format);
  FILE *f = s == ZR_OK ? fopen(path, "rb") : NULL;
  if (s == ZR_OK && !f)
    s = ZR_EIO;
  char buf[65536];
  size_t n;
  while (f && (n = fread(buf, 1, sizeof buf, f)) > 0)
    if (fwrite(buf, 1, n, stdout) != n) {
      s = ZR_EIO;
      break;
    }
  if (f)
    fclose(f);
  if (fflush(stdout) != 0)
    s = ZR_EIO;
  unlink(path);
  if (s != ZR_OK && r->diag.errors_printed == before)
    fprintf(stderr, "zrcube: cannot write the image to standard output: "
                    "%s\n", zr_status_str(s));
  return s;
}

/* +C on rank 0: the state to continue from, or none.  Returns -1 (and
   has printed why) when the state file must be refused. */
static int load_state(run *r, zr_par_progress *resume, int *have) {
  *have = 0;
  if (!r->opts.continue_trace || !r->state_path)
    return 0;
  char err[1024];
  resume->channels = r->opts.params.alpha ? 4 : 3;
  int rc = zr__state_read(r->state_path, r->fingerprint,
                          r->opts.params.width, r->opts.params.height,
                          resume, err, sizeof err);
  if (rc < 0) {
    fprintf(stderr, "zrcube: %s\n", err);
    return -1;
  }
  int passes, bands, band_rows;
  zr__par_render_layout(r->par, &r->render, &passes, &bands, &band_rows);
  if (rc == 0 && (resume->passes != passes || resume->bands != bands ||
                  resume->band_rows != band_rows)) {
    fprintf(stderr, "zrcube: refusing the state file '%s': it was made by "
                    "another version of zrcube (remove it to render from "
                    "the start)\n", r->state_path);
    zr__state_free(resume);
    return -1;
  }
  *have = rc == 0;
  if (*have)
    say(&r->diag, ZR_CLI_STREAM_RENDER, "zrcube: continuing '%s' from "
        "'%s'\n", r->output_path, r->state_path);
  return 0;
}

/*
 * The write on the writer's thread (par/writer.h): a context of its own,
 * without the diagnostics callback (the main thread prints meanwhile),
 * whose last error the main thread prints after the render.
 */
typedef struct thread_write {
  run *r;
  zr_context *ctx;
} thread_write;

static zr_status save_on_thread(zr_image *image, void *user) {
  thread_write *t = user;
  return write_image_in(t->ctx, t->r, image, t->r->output_path,
                        t->r->format);
}

/*
 * Rank 0 under mpirun, or one process of two threads or more, a PNG
 * file of the whole image with colours alone: its write starts before
 * the render and encodes rows as they are final, while the other ranks
 * render the last bands (zr__par_render's writer) or, in one process,
 * row by row beside the render's threads.  About 45 ns a pixel here (bench/write_rows.sh: a PNG write
 * of 2048x1536 and 2048x2048 images at the default level, 0.12-0.14
 * and 0.18-0.19 s, 39-45 ns a pixel at loads 8-16), which sizes the
 * bands left to the other ranks.  Returns 1 when started.
 */
#define WRITE_PIXEL_SECONDS 45e-9

static int start_writer(run *r, thread_write *t, zr_par_writer **w) {
  *w = NULL;
  t->r = r;
  t->ctx = NULL;
  if (r->rank != 0 ||
      (zr__par_size(r->par) < 2 && r->threads < 2) ||
      !r->opts.write_output ||
      r->opts.to_stdout || r->path || r->opts.params.alpha ||
      r->row0 != 0 || r->row1 != r->opts.params.height || r->col0 != 0 ||
      r->col1 != r->opts.params.width ||
      (r->format != ZR_FORMAT_PNG8 && r->format != ZR_FORMAT_PNG16))
    return 0;
  if (zr_context_new(&t->ctx) != ZR_OK)
    return 0;
  zr_context_set_png_level(t->ctx, r->opts.png_level);
  if (zr__par_writer_start(r->image, save_on_thread, t, w) != ZR_OK) {
    zr_context_free(t->ctx);
    t->ctx = NULL;
    return 0;
  }
  r->render.writer = *w;
  /* ZRCUBE_WRITE_PIXEL_SECONDS replaces the estimate (the tests make
     small renders leave most bands to the other ranks with it). */
  const char *given = getenv("ZRCUBE_WRITE_PIXEL_SECONDS");
  double pixel = given && *given ? strtod(given, NULL) : WRITE_PIXEL_SECONDS;
  r->render.write_row_seconds =
      (pixel > 0 ? pixel : 0) * (double)r->opts.params.width;
  return 1;
}

/* Step 5: render and write. */
static int render_and_write(run *r) {
  const zr_render_params *params = &r->opts.params;
  zr_status s = ZR_OK;
  zr__par_mark("image: allocating");
  if (r->rank == 0) {
    s = zr_image_new(params->width, params->height, &r->image);
    if (s != ZR_OK)
      fprintf(stderr, "zrcube: cannot make a %dx%d image: %s\n",
              params->width, params->height, zr_status_str(s));
  }
  if (zr__par_agree(r->par, s) != ZR_OK)
    return EXIT_SCENE;
  r->render.scene = r->scene;
  r->render.params = params;
  r->render.threads = r->threads;
  r->render.progress = r->progress.mode ? on_rows : NULL;
  r->render.progress_user = &r->progress;
  r->render.image = r->image;
  /* zr_image_new's pixels are zero (a fresh mapping for big images). */
  r->render.image_zero = r->image != NULL;
  r->render.row0 = r->row0;
  r->render.row1 = r->row1;
  r->render.col0 = r->col0;
  r->render.col1 = r->col1;
  r->render.band_done = r->rank == 0 ? band_done : NULL;
  r->render.band_user = r;
  r->render.band_seconds = r->opts.state_interval;
  r->render.resume = NULL;
  r->last_state_write = zr__par_now();
  r->state_failed = 0;
  zr_par_progress resume;
  memset(&resume, 0, sizeof resume);
  int have = 0;
  s = ZR_OK;
  if (r->rank == 0 && load_state(r, &resume, &have) < 0)
    s = ZR_EFORMAT;
  if (zr__par_agree(r->par, s) != ZR_OK)
    return EXIT_SCENE;
  if (have)
    r->render.resume = &resume;
  thread_write tw;
  zr_par_writer *writer = NULL;
  r->render.writer = NULL;
  r->render.write_row_seconds = 0;
  int threaded = start_writer(r, &tw, &writer);
  zr__par_mark("render start (image and writer ready)");
  double cpu = zr__par_cpu();
  s = r->path ? render_path(r) : zr__par_render(r->par, &r->render);
  r->render_cpu = zr__par_cpu() - cpu;
  zr__state_free(&resume);
  zr_status written = ZR_OK;
  zr__par_mark("render end");
  double write_start = zr__par_now();
  if (threaded) {
    /* The rest of the write, or its end after a failed render. */
    written = zr__par_writer_finish(writer, s != ZR_OK);
    r->render.writer = NULL;
  }
  if (r->progress.line_open && s == ZR_OK) {
    fputs("\n", stderr);
    r->progress.line_open = 0;
  }
  clear_progress_line(&r->progress);
  if (s != ZR_OK) {
    if (r->rank == 0) {
      const char *why = zr_context_last_error(r->ctx);
      if (s == ZR_ECANCELLED && signal_caught)
        fprintf(stderr, "zrcube: rendering stopped by %s; the image was "
                "not written\n", signal_caught == SIGINT ? "SIGINT"
                                                          : "SIGTERM");
      else if (*why)
        fputs(why, stderr);
      else
        fprintf(stderr, "zrcube: rendering failed: %s\n", zr_status_str(s));
    }
    if (threaded)
      zr_context_free(tw.ctx);
    return EXIT_SCENE;
  }
  s = ZR_OK;
  if (r->rank == 0 && r->opts.write_output) {
    /* With a writer, the time rank 0 still took to write after the
       render. */
    double start = threaded ? write_start : zr__par_now();
    unsigned before = r->diag.errors_printed;
    if (r->opts.to_stdout) {
      s = write_to_stdout(r);
    } else {
      if (threaded) {
        s = written;
        if (s != ZR_OK && *zr_context_last_error(tw.ctx)) {
          emit(&r->diag, ZR_CLI_STREAM_FATAL, zr_context_last_error(tw.ctx));
          r->diag.errors_printed++;
        }
      } else {
        s = write_image(r, r->image, r->output_path, r->format);
      }
      if (s != ZR_OK && r->diag.errors_printed == before)
        fprintf(stderr, "zrcube: cannot write '%s': %s\n", r->output_path,
                zr_status_str(s));
    }
    /* The image is whole: its state file has served. */
    if (s == ZR_OK && r->state_path)
      zr__state_remove(r->state_path);
    r->write_seconds = zr__par_now() - start;
  }
  zr__par_mark("image written");
  if (threaded)
    zr_context_free(tw.ctx);
  return zr__par_agree(r->par, s) == ZR_OK ? -1 : EXIT_SCENE;
}

/* -v under mpirun: each phase's time and what this rank sent, one
   line a rank on stderr, for bench/scale.sh's model; "process" is the
   CPU the whole process has taken so far (its start-up, MPI's included,
   the phases and the image written), the whole-process figure; "tail
   bands" are those the ranks but 0 rendered while rank 0 wrote, "tail
   rows joined" the rows of them rank 0 took once its encoder was done
   (0 on the other ranks). */
static void print_rank_times(const run *r) {
  zr_par_traffic t;
  zr__par_get_traffic(r->par, &t);
  fprintf(stderr,
          "zrcube: rank %d: wall s: parse %.4f gi %.4f radiosity %.4f "
          "render %.4f gather %.4f exchange %.4f; cpu s: parse %.4f "
          "gi %.4f radiosity %.4f render %.4f exchange %.4f process %.4f; "
          "sent B: scene %llu solution %llu pixels %llu; exchanges %llu; "
          "tail rows joined %d; tail bands %d\n",
          r->rank, r->parse_seconds, r->gi_seconds, r->radiosity_seconds,
          r->render.render_seconds, r->render.gather_seconds,
          t.team_seconds, r->parse_cpu, r->gi_cpu, r->radiosity_cpu,
          r->render_cpu, t.team_cpu_seconds, zr__par_cpu(),
          (unsigned long long)t.bcast_bytes_sent,
          (unsigned long long)t.team_bytes_sent,
          (unsigned long long)t.pixel_bytes_sent,
          (unsigned long long)t.team_calls, r->render.tail_root_rows,
          r->render.tail_bands);
}

/* A time as POV-Ray's statistics give it. */
static void print_time(FILE *out, const char *label, double seconds) {
  long whole = (long)seconds;
  fprintf(out, "  %-18s%ld hours %2ld minutes %2ld seconds (%.3f seconds)\n",
          label, whole / 3600, whole / 60 % 60, whole % 60, seconds);
}

/*
 * +V: the statistics at the end, in the layout POV-Ray 3.7 prints them
 * (measured: `povray +V` on a small scene; its per-shape intersection
 * table and the counts zRcube does not keep are left out), with the
 * ranks and threads of the run.
 */
static void print_statistics(run *r) {
  const zr_render_stats *st = &r->render.stats;
  const zr_render_params *p = &r->opts.params;
  zr_scene_info info;
  zr_scene_get_info(r->scene, &info);
  static const char rule[] = "-------------------------------------------"
                             "---------------------------------";
  unsigned long long pixels = st->camera_rays,
                     samples = st->supersample_rays,
                     rays = st->camera_rays + st->supersample_rays +
                            st->reflected_rays + st->refracted_rays;
  int ranks = zr__par_size(r->par);
  /* Through the statistics stream (+GS, -GS), which may go to a file. */
  char *text = NULL;
  size_t len = 0;
  FILE *out = open_memstream(&text, &len);
  if (!out)
    return;
  fprintf(out, "%s\nParser Statistics\n%s\n", rule, rule);
  fprintf(out, "%-18s%9zu\n%-18s%9zu\n%-18s%9zu\n%-18s%9zu\n",
          "Finite Objects:", info.finite_primitives, "Infinite Objects:",
          info.infinite_primitives, "Light Sources:", info.lights, "Total:",
          info.finite_primitives + info.infinite_primitives + info.lights);
  fprintf(out, "%s\nParser Time\n", rule);
  print_time(out, "Parse Time:", r->parse_seconds);
  fprintf(out, "%s\nRender Statistics\nImage Resolution %d x %d\n%s\n",
          rule, p->width, p->height, rule);
  fprintf(out, "%-10s%14llu   %-10s%14llu   Smpls/Pxl: %.2f\n",
          "Pixels:", pixels, "Samples:", samples,
          pixels ? (double)samples / (double)pixels : 0.0);
  fprintf(out, "%-10s%14llu   %-10s%14llu\n", "Rays:", rays,
          "Supersampled pixels:", (unsigned long long)st->supersampled_pixels);
  fprintf(out, "%s\n%-24s%10llu\n%-24s%10llu\n%-24s%10llu\n%s\n",
          rule, "Shadow Ray Tests:", (unsigned long long)st->shadow_rays,
          "Reflected Rays:", (unsigned long long)st->reflected_rays,
          "Refracted Rays:", (unsigned long long)st->refracted_rays, rule);
  if (info.photons_shot > 0)
    fprintf(out, "%-26s%12llu\n%-26s%12llu\n%s\n",
            "Number of photons shot:", info.photons_shot,
            "Surface photons stored:", info.photons_stored, rule);
  if (info.media_photons_stored > 0)
    fprintf(out, "%-26s%12llu\n%-26s%12.6g\n%s\n",
            "Media photons stored:", info.media_photons_stored,
            "Media photons radius:", info.media_photons_radius, rule);
  fprintf(out, "Render Time:\n");
  if (r->gi_method == ZR_GI_HIERARCHICAL || r->gi_method == ZR_GI_CACHE)
    print_time(out, "Radiosity Time:", r->radiosity_seconds + r->gi_seconds);
  else
    fprintf(out, "  %-18sNo radiosity\n", "Radiosity Time:");
  print_time(out, "Trace Time:", r->render.render_seconds);
  fprintf(out, "              using %d rank%s x %d thread%s\n", ranks,
          ranks == 1 ? "" : "s", r->threads, r->threads == 1 ? "" : "s");
  print_time(out, "Write Time:", r->write_seconds);
  if (fclose(out) == 0 && text)
    emit(&r->diag, ZR_CLI_STREAM_STATISTICS, text);
  free(text);
}

/* --parse-only: what the scene holds, on stdout, one "key: value" a
   line so scripts (bench/parse.sh) can pick fields. */
static void print_scene_info(const run *r) {
  zr_scene_info info;
  zr_scene_get_info(r->scene, &info);
  printf("scene: %s\n"
         "objects: %zu\n"
         "primitives: %zu\n"
         "finite primitives: %zu\n"
         "infinite primitives: %zu\n"
         "lights: %zu\n"
         "camera: %s\n"
         "parse seconds: %.4f\n"
         "parse steps: %llu\n"
         "memory peak: %llu\n",
         r->opts.input, info.objects, info.primitives,
         info.finite_primitives, info.infinite_primitives, info.lights,
         info.has_camera ? "yes" : "no (the default)", r->parse_seconds,
         info.parse_steps, zr_context_memory_peak(r->ctx));
  /* Whether POV-Ray would gamma-correct the picture (a legacy scene
     without assumed_gamma: no, zr_scene_file_gamma). */
  printf("assumed gamma: %g%s\n", zr_scene_assumed_gamma(r->scene),
         zr_scene_file_gamma(r->scene) > 0.0
             ? " (legacy scene: gamma correction off)"
             : "");
}

/* Frees what one frame made. */
static void end_frame(run *r) {
  signal_ctx = NULL; /* the context goes: no signal may cancel it now */
  zr_image_free(r->image);
  free(r->state_rad);
  r->state_rad = NULL;
  zr_radiosity_free(r->rad);
  zr_gi_cache_free(r->gi);
  zr_path_free(r->path);
  zr_scene_free(r->scene);
  zr__bundle_free(&r->bundle);
  free_digests(r);
  zr_context_free(r->ctx);
  r->image = NULL;
  r->rad = NULL;
  r->gi = NULL;
  r->path = NULL;
  r->scene = NULL;
  r->ctx = NULL;
  r->opts.params.radiosity = NULL;
  r->opts.params.gi_cache = NULL;
  r->opts.params.path = NULL;
  free(r->output_path);
  free(r->state_path);
  r->output_path = NULL;
  r->state_path = NULL;
  memset(&r->diag, 0, sizeof r->diag);
}

/* One frame (or the still image): parse with its clock, light, render,
   write.  Returns an exit status or -1 for success. */
static int run_frame(run *r, const zr_cli_frame *frame) {
  r->frame = frame;
  r->diag.console = r->opts.stream_console;
  r->diag.files = r->rank == 0 ? r->stream_files : NULL;
  r->diag.last_stream = ZR_CLI_STREAM_WARNING;
  if (r->still_path) {
    r->output_path = r->digits ? zr__cli_frame_name(r->still_path,
                                                    frame->number, r->digits)
                               : strdup(r->still_path);
    if (!r->output_path) {
      fprintf(stderr, "zrcube: out of memory\n");
      return EXIT_SCENE;
    }
    /* The state file of +C, beside the image: kept while a render
       writes a file (not with +O- or -F, nor for --parse-only). */
    if (r->opts.write_output && !r->opts.parse_only &&
        !(r->state_path = zr__state_path(r->output_path))) {
      fprintf(stderr, "zrcube: out of memory\n");
      return EXIT_SCENE;
    }
  }
  if (r->digits && r->rank == 0 && r->opts.verbose)
    say(&r->diag, ZR_CLI_STREAM_RENDER, "zrcube: frame %ld (%zu of %zu), "
        "clock %g -> %s\n", frame->number,
        (size_t)(frame - r->frames) + 1, r->n_frames, frame->clock.clock,
        r->output_path ? r->output_path : "standard output");
  /* +C in an animation: a frame whose image is there and whose state
     file is not was finished before. */
  if (r->opts.continue_trace && r->digits && r->state_path) {
    struct stat st;
    int done = r->rank == 0 && stat(r->output_path, &st) == 0 &&
               stat(r->state_path, &st) != 0;
    if (zr__par_agree(r->par, done ? ZR_EINVAL : ZR_OK) != ZR_OK)
      return -1;
  }
  int status = read_scene(r);
  if (status < 0 && r->opts.parse_only) {
    if (r->rank == 0)
      print_scene_info(r);
    return -1;
  }
  if (status < 0)
    status = set_up_gi(r);
  if (status < 0)
    status = render_and_write(r);
  if (status < 0 && r->rank == 0 && r->opts.verbose)
    print_statistics(r);
  if (status < 0 && r->opts.verbose)
    print_rank_times(r);
  return status;
}

/* The stream files of +GDfile ... (rank 0), rewritten for each run. */
static int open_streams(run *r) {
  for (int i = 0; i < ZR_CLI_STREAMS; i++) {
    const char *name = r->opts.stream_file[i];
    if (!name || r->rank != 0)
      continue;
    /* Streams sent to one file share it. */
    for (int k = 0; k < i && !r->stream_files[i]; k++)
      if (r->opts.stream_file[k] && !strcmp(r->opts.stream_file[k], name))
        r->stream_files[i] = r->stream_files[k];
    if (!r->stream_files[i] && !(r->stream_files[i] = fopen(name, "w"))) {
      fprintf(stderr, "zrcube: cannot write the text stream file '%s': "
                      "%s\n", name, strerror(errno));
      return -1;
    }
  }
  return 0;
}

static void close_streams(run *r) {
  for (int i = 0; i < ZR_CLI_STREAMS; i++) {
    if (!r->stream_files[i])
      continue;
    int shared = 0;
    for (int k = i + 1; k < ZR_CLI_STREAMS; k++)
      if (r->stream_files[k] == r->stream_files[i])
        shared = 1;
    if (!shared)
      fclose(r->stream_files[i]);
    r->stream_files[i] = NULL;
  }
}

/*
 * Whole frames per rank: with more frames than ranks (or when asked,
 * --frames-per-rank), rank k renders frames k, k + n, ... alone, from
 * the files as it finds them (a cluster's ranks share the scene's
 * folder, as they share the INI files), and writes them itself; else
 * every rank works on every frame, row by row.  A frame's pixels do not
 * depend on how many ranks made it, so the bytes are the same.
 */
static int frames_per_rank(const run *r) {
  int size = zr__par_size(r->world);
  if (size < 2 || r->opts.parse_only || r->opts.to_stdout)
    return 0;
  if (r->opts.frames_per_rank >= 0)
    return r->opts.frames_per_rank;
  return r->digits > 0 && r->n_frames >= (size_t)size;
}

int main(int argc, char **argv) {
  run r;
  memset(&r, 0, sizeof r);
  zr__par_mark("main() entered");
  zr_status s = zr__par_init(&argc, &argv, &r.world);
  zr__par_mark("MPI joined (zr__par_init)");
  if (s != ZR_OK) {
    fprintf(stderr, "zrcube: cannot start MPI: %s\n", zr_status_str(s));
    return EXIT_SCENE;
  }
  r.par = r.world;
  r.rank = zr__par_rank(r.par);
  if (zr__par_team(r.par, &r.team) != ZR_OK) {
    if (r.rank == 0)
      fprintf(stderr, "zrcube: out of memory\n");
    zr__par_finalize(r.par);
    return EXIT_SCENE;
  }
  int status = read_command_line(&r, argc, argv);
  if (status < 0 &&
      zr__par_agree(r.world, open_streams(&r) ? ZR_EIO : ZR_OK) != ZR_OK)
    status = EXIT_USAGE;
  if (status < 0) {
    int split = frames_per_rank(&r);
    int me = zr__par_rank(r.world), size = zr__par_size(r.world);
    if (split && zr__par_solo(r.world, &r.solo) != ZR_OK) {
      fprintf(stderr, "zrcube: out of memory\n");
      status = EXIT_SCENE;
    }
    int local = -1;
    for (size_t i = 0; status < 0 && local < 0 && i < r.n_frames; i++) {
      if (split && (int)(i % (size_t)size) != me)
        continue;
      r.par = split ? r.solo : r.world;
      r.rank = zr__par_rank(r.par);
      /* A frame a rank renders alone is solved by it alone. */
      if (zr__par_team(r.par, &r.team) != ZR_OK) {
        local = EXIT_SCENE;
        break;
      }
      local = run_frame(&r, &r.frames[i]);
      if (local >= 0 && r.diag.hidden_error[0])
        fputs(r.diag.hidden_error, stderr);
      end_frame(&r);
    }
    r.par = r.world;
    r.rank = zr__par_rank(r.world);
    if (status < 0) {
      /* With frames per rank, each rank stopped at its own failure; all
         leave with the same status. */
      if (split) {
        zr_status agreed = zr__par_agree(r.world, local < 0 ? ZR_OK
                                                            : ZR_EINVAL);
        status = agreed == ZR_OK ? EXIT_SUCCESS : EXIT_SCENE;
      } else {
        status = local < 0 ? EXIT_SUCCESS : local;
      }
    }
  }
  signal_ctx = NULL;
  end_frame(&r);
  close_streams(&r);
  free(r.still_path);
  free(r.frames);
  zr__cli_free(&r.opts);
  clear_progress_line(&r.progress);
  zr__par_finalize(r.solo);
  zr__par_mark("MPI_Finalize");
  zr__par_finalize(r.world);
  zr__par_mark("leaving main()");
  if (signal_caught) {
    /* Cancelled by a signal: end as the signal would have. */
    int sig = signal_caught;
    signal(sig, SIG_DFL);
    raise(sig);
  }
  return status;
}
