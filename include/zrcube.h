/*
 * zrcube.h - the public interface of libzrcube.
 *
 * libzrcube reads POV-Ray 3.7 scene files, ray traces them with POV-Ray's
 * lighting model and writes images.  This is the only header a program
 * linking the library needs.  Everything is reached through opaque types
 * with the zr_ prefix; fallible calls return a zr_status (0 is success,
 * failures are negative and never renumbered); the library keeps no global
 * state, never prints and never exits: diagnostics go to a callback the
 * caller sets on a zr_context.
 *
 * A parsed zr_scene is immutable, so any number of threads may render
 * pixels of it at once.  Rendering is split in two passes so that a
 * picture is the same bytes however its pixels are spread over processes
 * and threads:
 *   1. zr_render_pixels() with centres == NULL traces one ray through the
 *      centre of each listed pixel;
 *   2. when antialiasing is on, zr_render_pixels() with the complete image
 *      of centres from pass 1 supersamples the pixels that differ from
 *      their neighbours by more than the threshold.
 * zr_render_image() does both passes for a whole image with
 * zr_render_params.threads threads.
 *
 * Threads, object by object:
 *   zr_context   one thread at a time (set-up, then the calls that take
 *                it); zr_context_cancel() from any thread at any time;
 *                the diagnostics and progress callbacks are called from
 *                the call's threads, never two at once.
 *   zr_scene     immutable once parsed: any number of threads may render
 *                it, solve radiosity for it and read its info at once.
 *   zr_radiosity, zr_gi_cache  read-only once solved or pretraced: any
 *                number of renders may share one; solve, pretrace, load
 *                and free are one thread's.
 *   zr_image     plain memory: one writer, or any number of readers.
 *   parameter and stats structs  the caller's; the library reads
 *                params during the call and adds to stats from the
 *                calling thread only.
 * Calls on different objects never share state: two scenes may be
 * parsed and rendered at once on two contexts.
 */
#ifndef ZRCUBE_H
#define ZRCUBE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(ZR_BUILDING_LIBRARY) && defined(__GNUC__)
#define ZR_API __attribute__((visibility("default")))
#else
#define ZR_API
#endif

#define ZR_VERSION_MAJOR 0
#define ZR_VERSION_MINOR 1
#define ZR_VERSION_PATCH 0
#define ZR_VERSION_STRING "0.1.0"

/* Status codes: one list, values never renumbered, new ones appended. */
#define ZR_STATUS_MAP(X)                                                   \
  X(OK, 0, "success")                                                      \
  X(ENOMEM, -1, "out of memory")                                           \
  X(EIO, -2, "input/output error")                                         \
  X(ESYNTAX, -3, "syntax error")                                           \
  X(EUNDEFINED, -4, "undefined identifier")                                \
  X(EUNSUPPORTED, -5, "unsupported feature")                               \
  X(EINVAL, -6, "invalid argument")                                        \
  X(EFORMAT, -7, "malformed or unsupported file format")                   \
  X(ENOTFOUND, -8, "file not found")                                       \
  X(ELIMIT, -9, "limit exceeded")                                          \
  X(ESCENE, -10, "invalid scene")                                          \
  X(EMPI, -11, "message passing error")                                    \
  X(ETHREAD, -12, "thread error")                                          \
  X(EEXIST, -13, "file exists")                                           \
  X(EACCESS, -14, "file refused by the I/O restrictions")                \
  X(ECANCELLED, -15, "cancelled by the caller")

typedef enum zr_status {
#define ZR_STATUS_ENUM_(name, value, text) ZR_##name = value,
  ZR_STATUS_MAP(ZR_STATUS_ENUM_)
#undef ZR_STATUS_ENUM_
} zr_status;

/* A static English text for a status code; never NULL. */
ZR_API const char *zr_status_str(zr_status status);

/* The library's version string, "MAJOR.MINOR.PATCH". */
ZR_API const char *zr_version(void);

/* ------------------------------------------------------------------ */
/* Diagnostics and context                                            */
/* ------------------------------------------------------------------ */

typedef enum zr_diag_level {
  ZR_DIAG_ERROR = 0,
  ZR_DIAG_WARNING = 1,
  ZR_DIAG_NOTE = 2,   /* "in file included from ...", context lines */
  ZR_DIAG_DEBUG = 3   /* #debug output of a scene */
} zr_diag_level;

/*
 * One diagnostic.  file is NULL and line/column are 0 when the message has
 * no place in a scene file.  text is the complete message formatted like a
 * compiler's: "scene.pov:12:7: error: message", the include chain, the
 * source line and a caret under the column, ending in a newline.  Both
 * message and text are safe to print on a terminal: control bytes and
 * bytes that are not UTF-8 from the scene show as \xNN, an error's or
 * warning's message stops after 2048 bytes with "...", and a long source
 * line is quoted as a window of 70 columns each side of the caret.  All
 * pointers are valid only during the callback.  offset is the byte offset
 * in file of line:column (0 when there is no place), length the number
 * of bytes the message points at there (the token; 0 when unknown), so
 * an editor can underline the span without counting columns itself.
 * New members are only ever added at the end: the library allocates
 * this struct, so a caller built against an older header reads a prefix.
 */
typedef struct zr_diag {
  zr_diag_level level;
  zr_status status;
  const char *file;
  int line;
  int column;
  const char *message;
  const char *text;
  size_t offset;
  size_t length;
} zr_diag;

typedef void (*zr_diag_fn)(const zr_diag *diag, void *user);

/*
 * How the parser reads a file: fill *bytes with malloc'ed contents (the
 * library frees them) and *size.  Return ZR_ENOTFOUND when the file does
 * not exist.  The default reader uses stdio; a parallel program swaps in a
 * reader that serves files broadcast from rank 0.
 */
typedef zr_status (*zr_read_fn)(const char *path, char **bytes, size_t *size,
                                void *user);

typedef struct zr_context zr_context;

ZR_API zr_status zr_context_new(zr_context **out);
ZR_API void zr_context_free(zr_context *ctx);
/* Without a callback diagnostics are dropped (the status still tells). */
ZR_API void zr_context_set_diag(zr_context *ctx, zr_diag_fn fn, void *user);
ZR_API void zr_context_set_reader(zr_context *ctx, zr_read_fn fn, void *user);
/* Directories searched by #include after the including file's own. */
ZR_API zr_status zr_context_add_include_path(zr_context *ctx, const char *dir);
/*
 * The render size a scene reads as image_width and image_height (POV-Ray
 * takes them from +W and +H): set it before parsing.  Default 320x240.
 * ZR_EINVAL for a size below 1.
 */
ZR_API zr_status zr_context_set_render_size(zr_context *ctx, int width,
                                            int height);
/*
 * What a scene reads while it is parsed besides the render size: the
 * animation clock (POV-Ray's "Built-in Float Identifiers" clock,
 * clock_delta, clock_on, frame_number, initial_frame, final_frame,
 * initial_clock, final_clock; reference section 3.2.1, "Animation
 * Options") and the language version the scene starts in (+MV).
 * Size rule: size is sizeof (zr_parse_options) as the caller was
 * compiled; the library reads only the fields that fit in size, and
 * fields added later (always at the end) keep their defaults for
 * callers built before them.  zr_parse_options_init() fills the
 * defaults of a still image: every clock value 0, version 3.7.
 */
typedef struct zr_parse_options {
  size_t size;          /* sizeof (zr_parse_options) */
  double clock;         /* +K, or the frame's clock in an animation */
  double clock_delta;   /* clock step between frames; 0 for a still */
  int clock_on;         /* 1 when a clock was given or animating */
  int frame_number;
  int initial_frame, final_frame;
  double initial_clock, final_clock;
  double version;       /* +MV: 3.7 by default */
} zr_parse_options;

ZR_API void zr_parse_options_init(zr_parse_options *o);
/* Copies o into ctx for the parses that follow; ZR_EINVAL when o->size
   is too small to hold the size field itself or version is not
   positive. */
ZR_API zr_status zr_context_set_parse_options(zr_context *ctx,
                                              const zr_parse_options *o);
/*
 * Declares a float for the parses that follow, as the first statement
 * of the scene would ("#declare name = value;", POV-Ray's INI option
 * Declare=IDENTIFIER=FLOAT).  A later call with the same name replaces
 * the value.  ZR_EINVAL when name is not an identifier (a letter or '_'
 * then letters, digits and '_') or value is not finite.
 */
ZR_API zr_status zr_context_declare(zr_context *ctx, const char *name,
                                    double value);
/*
 * A file read before the scene, as if its first line were #include
 * "path" (POV-Ray's Include_Header=file, +HIfile): found where #include
 * looks.  NULL removes it.
 */
ZR_API zr_status zr_context_set_header_include(zr_context *ctx,
                                               const char *path);
/*
 * The work budget of one parse: every directive run, every macro call
 * and every pass through a #while, #for or #zfor body is one step.  A
 * scene that takes more steps stops with ZR_ELIMIT and a located error
 * (a loop whose condition never turns false, macros that branch into
 * each other without end), instead of parsing forever.  0: no limit.
 * The default, ZR_DEFAULT_WORK_LIMIT, is about a minute of the simplest
 * loop and more than a hundred times what the most demanding stock
 * scene of POV-Ray 3.7 takes.
 */
#define ZR_DEFAULT_WORK_LIMIT 200000000ULL
ZR_API void zr_context_set_work_limit(zr_context *ctx,
                                      unsigned long long steps);
/* The older name of the work budget (it counted loop passes only). */
#define ZR_DEFAULT_LOOP_LIMIT ZR_DEFAULT_WORK_LIMIT
ZR_API void zr_context_set_loop_limit(zr_context *ctx,
                                      unsigned long long iterations);
/*
 * I/O restrictions: which files a scene may open.  They apply to every
 * file a scene names (#include, #fopen and #read/#write, image_map,
 * bump_map, material_map and height_field images, density_file, text
 * fonts, file_exists()), after POV-Ray's [File I/O Security] settings
 * of the same names:
 *   ZR_IO_RESTRICTED (the default): a scene reads any file it names by
 *     a relative name, found from the folder of the file naming it or
 *     from an include path ("../x.inc" too), as POV-Ray 3.7 does; a
 *     name that starts with '/' only below the main scene file's
 *     folder, the working directory, the include paths, POV-Ray's
 *     include folder and the folders added with
 *     zr_context_add_read_path() or zr_context_add_write_path(); it
 *     writes only below the working directory and the write paths;
 *   ZR_IO_STRICT: relative names are confined to those folders too
 *     (the earlier default), writes as above;
 *   ZR_IO_READ_ONLY: reads anywhere, writes as above;
 *   ZR_IO_NONE: no folder is checked.
 * A path is judged after its symbolic links are resolved, and the file
 * opened is checked again once open.  Whatever the setting, only regular
 * files are read or written: devices, FIFOs, sockets and directories are
 * refused by name.  A refused file is never read, so no message shows
 * its contents; the scene stops with ZR_EACCESS at the name's location.
 * Files the caller names (zr_scene_parse_file, zr_image_read,
 * zr_image_write, zr_radiosity_save and _load) are not confined to these
 * folders, but must be regular files too.  A reader set with
 * zr_context_set_reader() takes the place of the disk, and what it
 * serves is its own business: the restrictions guard the library's own
 * reading.
 */
typedef enum zr_io_restrictions {
  ZR_IO_RESTRICTED = 0,
  ZR_IO_READ_ONLY = 1,
  ZR_IO_NONE = 2,
  ZR_IO_STRICT = 3
} zr_io_restrictions;

/* ZR_EINVAL for a value outside the enumeration. */
ZR_API zr_status zr_context_set_io_restrictions(zr_context *ctx,
                                                zr_io_restrictions mode);
/*
 * Adds a folder (and everything below it) where scenes may read, or read
 * and write.  A relative name is taken from the working directory now,
 * and symbolic links are resolved now.  ZR_ENOTFOUND when dir does not
 * exist, ZR_EINVAL when it is not a directory.
 */
ZR_API zr_status zr_context_add_read_path(zr_context *ctx, const char *dir);
ZR_API zr_status zr_context_add_write_path(zr_context *ctx, const char *dir);

/*
 * Called with every file the library's own reader reads (not a reader
 * set with zr_context_set_reader()), under the name the parser asked
 * for: a parallel program records the files to serve them to its other
 * processes.  A status other than ZR_OK fails the read with it.
 */
typedef zr_status (*zr_read_observer_fn)(const char *path,
                                         const char *bytes, size_t size,
                                         void *user);
ZR_API void zr_context_set_read_observer(zr_context *ctx,
                                         zr_read_observer_fn fn, void *user);

/*
 * Whether a scene's #fopen ... write/append and #write reach the disk
 * (default 1).  With 0 the directives are still parsed, their values
 * computed and their file names checked for the same errors of syntax,
 * but no file is created or changed: a parallel program parses the
 * scene on every process and lets only one of them write.  What the
 * scene reads back is whatever the reader serves.
 */
ZR_API void zr_context_set_scene_writes(zr_context *ctx, int enabled);

/*
 * The memory budget of everything made with ctx (scenes, their token
 * arrays, arrays, meshes and images, radiosity solutions): the large
 * allocations are charged to it before they are made, and one that does
 * not fit stops the parse or solve with ZR_ELIMIT and a message, rather
 * than the process growing until the system kills it.  The default is
 * half of physical memory, or three quarters of the process's address
 * space or data limit (ulimit -v, -d) when that is lower.  0: no limit.
 * Scenes made with ctx share its budget, and may outlive ctx.
 */
ZR_API void zr_context_set_memory_limit(zr_context *ctx,
                                        unsigned long long bytes);
ZR_API unsigned long long zr_context_memory_limit(const zr_context *ctx);
/* The most memory charged to ctx's budget at once so far. */
ZR_API unsigned long long zr_context_memory_peak(const zr_context *ctx);
/*
 * The largest file a scene may read (the scene file, #include, image
 * and height-field maps, fonts, density files, radiosity files): a
 * larger regular file is refused before it is read, and a device or
 * pipe that gives more than this (#include "/dev/zero") is cut off with
 * ZR_ELIMIT.  0: no limit.  Default ZR_DEFAULT_FILE_LIMIT (1 GiB).
 */
#define ZR_DEFAULT_FILE_LIMIT (1ULL << 30)
ZR_API void zr_context_set_file_limit(zr_context *ctx,
                                      unsigned long long bytes);
/*
 * The zlib compression level of the PNG images written with ctx, 0 (no
 * compression) to 9 (smallest, slowest); ZR_EINVAL outside.  Default
 * ZR_DEFAULT_PNG_LEVEL, chosen so that writing costs a small part of a
 * small render (issue 13, measured in bench/png_level.sh).
 */
#define ZR_DEFAULT_PNG_LEVEL 1
ZR_API zr_status zr_context_set_png_level(zr_context *ctx, int level);
/*
 * Threads the parses that follow may use, the caller's among them: a
 * mesh or mesh2 of many triangles has its hierarchy built by up to this
 * many.  1 (the default) builds everything on the calling thread;
 * below 1 counts as 1.  The scene is the same for any number.
 */
ZR_API void zr_context_set_threads(zr_context *ctx, int threads);
/*
 * What finds a ray's triangles in the meshes (mesh, mesh2) of the
 * scenes parsed next: ZR_ACCEL_BUILTIN, zRcube's own hierarchy; or
 * ZR_ACCEL_EMBREE, Embree 3's (a build configured --with-embree), whose
 * single-precision answer names the candidate triangles that zRcube's
 * double-precision test then confirms, so t, the normal and the surface
 * coordinates are the built-in ones; rays that graze an edge within
 * single precision may find a neighbour or miss (issue 13).  Default
 * ZR_ACCEL_DEFAULT: Embree when the library was built with it.
 * ZR_EUNSUPPORTED for Embree in a build without it, ZR_EINVAL outside
 * the enumeration.
 */
typedef enum zr_accel {
  ZR_ACCEL_BUILTIN = 0,
  ZR_ACCEL_EMBREE = 1,
  ZR_ACCEL_DEFAULT = 2
} zr_accel;
ZR_API zr_status zr_context_set_accel(zr_context *ctx, zr_accel accel);
/* The message of the last error reported through ctx ("" when none). */
ZR_API const char *zr_context_last_error(const zr_context *ctx);

/*
 * Progress and cancel.  A long call (zr_scene_parse_file and _string,
 * zr_radiosity_solve, zr_gi_cache_pretrace, zr_render_image) tells the
 * context's progress callback how far it is, and stops with
 * ZR_ECANCELLED, freeing what it made, when the callback returns
 * non-zero or zr_context_cancel() was called.  Phases and their units:
 *   ZR_PHASE_PARSE      tokens read and directive steps taken; total 0
 *                       (not known in advance);
 *   ZR_PHASE_RADIOSITY  refine-and-solve rounds done of the most there
 *                       may be (the solve may end sooner), told again
 *                       at every sweep (or 64th shot) of each round;
 *   ZR_PHASE_PRETRACE   pixels of the irradiance cache's passes done of
 *                       total;
 *   ZR_PHASE_RENDER     rows rendered of total (both passes when
 *                       antialiasing is on).
 * The callback is called at most once per row, per pretrace batch, per
 * solver sweep and per 4096 tokens or steps, from the calling thread
 * or, with threads, from any of the call's threads but never two at
 * once; it must not call back into the library on the same objects.  A
 * call
 * cancelled this way returns within one row of each of its threads (the
 * render), one batch (the pretrace), one sweep (the solve) or 4096
 * tokens (the parse).
 */
typedef enum zr_phase {
  ZR_PHASE_PARSE = 0,
  ZR_PHASE_RADIOSITY = 1,
  ZR_PHASE_PRETRACE = 2,
  ZR_PHASE_RENDER = 3
} zr_phase;

typedef struct zr_progress {
  zr_phase phase;
  uint64_t done;
  uint64_t total; /* 0: not known in advance */
} zr_progress;

/* Returns 0 to go on, non-zero to cancel the call. */
typedef int (*zr_progress_fn)(const zr_progress *progress, void *user);
ZR_API void zr_context_set_progress(zr_context *ctx, zr_progress_fn fn,
                                    void *user);
/*
 * cancel != 0 asks every call running with ctx to stop with
 * ZR_ECANCELLED, and every later one to stop at once, until
 * zr_context_cancel(ctx, 0).  Safe from any thread and from a signal
 * handler (it stores one atomic flag).
 */
ZR_API void zr_context_cancel(zr_context *ctx, int cancel);

/* ------------------------------------------------------------------ */
/* Scenes                                                             */
/* ------------------------------------------------------------------ */

typedef struct zr_scene zr_scene;

ZR_API zr_status zr_scene_parse_file(zr_context *ctx, const char *path,
                                     zr_scene **out);
/* name is what messages call the text (for example "<string>"). */
ZR_API zr_status zr_scene_parse_string(zr_context *ctx, const char *name,
                                       const char *text, size_t size,
                                       zr_scene **out);
ZR_API void zr_scene_free(zr_scene *scene);

/* What a scene holds, for --parse-only and for tests. */
typedef struct zr_scene_info {
  size_t objects;          /* top-level objects as written */
  size_t primitives;       /* after unions are flattened */
  size_t lights;
  size_t finite_primitives;
  size_t infinite_primitives; /* planes and the like, kept out of the BVH */
  int has_camera;
  /* global_settings { radiosity { } }: the scene asks for radiosity */
  int has_radiosity;
  /* Steps the parse took against the work budget
     (zr_context_set_work_limit). */
  unsigned long long parse_steps;
  /* global_settings { photons { } }: the photons shot at the targets
     (the rays traced from the lights) and those stored where they
     landed, as povray +V counts them ("Number of photons shot",
     "Surface photons stored"); 0 without photons. */
  unsigned long long photons_shot, photons_stored;
  /* photons { media N }: the photons stored in media ("Media photons
     stored") and their gather radius (0 without media photons). */
  unsigned long long media_photons_stored;
  double media_photons_radius;
} zr_scene_info;

ZR_API void zr_scene_get_info(const zr_scene *scene, zr_scene_info *info);

/* ------------------------------------------------------------------ */
/* Teams: processes that share one computation                        */
/* ------------------------------------------------------------------ */

/*
 * A team is a group of processes (MPI ranks, typically) that compute one
 * radiosity solution or irradiance cache together: each member does its
 * share of the work, chosen by rank in a fixed order, and the members
 * exchange their results through allgather, which the caller provides.
 * The library never sees how the members talk (zrcube_mpi.h builds a
 * team on an MPI communicator), and every member ends with the same
 * bytes as one process alone would compute.
 *
 * allgather is collective: every member calls it at the same points with
 * the same counts (counts[r]: the bytes member r contributes); mine holds
 * counts[rank] bytes, and all receives every member's bytes one after
 * the other in rank order.  It returns ZR_OK, or a failure on every
 * member alike.  A team of size 1 (or no team) works alone.
 */
typedef zr_status (*zr_allgather_fn)(void *user, const void *mine,
                                     void *all, const size_t *counts);

typedef struct zr_team {
  int rank; /* 0 .. size - 1 */
  int size;
  zr_allgather_fn allgather;
  void *user;
} zr_team;

/*
 * The processes that parse the scenes of ctx together (NULL, the
 * default: this one alone): each member builds its share of the
 * hierarchy of every large mesh (mesh, mesh2) and the members exchange
 * the parts, so the scene is the same bytes as one process alone builds.
 * Every member calls zr_scene_parse_file or zr_scene_parse_string with
 * the same text at the same time, each call being collective; members
 * that read other bytes (a file that differs between hosts) notice it
 * at their next exchange (every exchange first compares the data it
 * stands for) and each builds alone from then on, and a member whose
 * parse fails still takes part until the call returns.  team must
 * outlive the parses.
 */
ZR_API void zr_context_set_team(zr_context *ctx, const zr_team *team);

/* ------------------------------------------------------------------ */
/* Radiosity                                                          */
/* ------------------------------------------------------------------ */

/*
 * A hierarchical radiosity solution of a scene (Hanrahan, Salzman and
 * Aupperle 1991) on the exact surfaces of its primitives, computed once
 * for every view.  It refers to the scene it was solved for, which must
 * outlive it; it is read-only once built, so threads may share it.
 */
typedef struct zr_radiosity zr_radiosity;

/* Which rule refines links (zr_radiosity_params.criterion). */
typedef enum zr_rad_criterion {
  ZR_RAD_CRITERION_BF = 0,   /* Hanrahan's B F A with the oracle factor */
  ZR_RAD_CRITERION_ERROR = 1 /* the light a link may misplace */
} zr_rad_criterion;

/* How a ray hit reads the solution (zr_radiosity_params.lookup). */
typedef enum zr_rad_lookup {
  ZR_RAD_LOOKUP_GATHER = 0, /* final gather over the element's links */
  ZR_RAD_LOOKUP_SMOOTH = 1  /* elements smoothed over their corners */
} zr_rad_lookup;

/* The solver (zr_radiosity_params.shooting). */
typedef enum zr_rad_solver {
  ZR_RAD_GATHERING = 0, /* Jacobi-style gathering sweeps */
  ZR_RAD_SHOOTING = 1   /* progressive Southwell shooting */
} zr_rad_solver;

/*
 * Parameter structs (zr_radiosity_params, zr_gi_params,
 * zr_render_params) start with their size: the _init function sets it
 * to sizeof the struct the caller was compiled with, and the library
 * takes the members that size covers and its defaults for members added
 * after it, so the structs can grow without breaking programs built
 * against an older header.  A struct not made by its _init function
 * (size 0) is refused with ZR_EINVAL.
 */
typedef struct zr_radiosity_params {
  size_t size;          /* sizeof (zr_radiosity_params), set by _init */
  /* Refine a link while B_source * F * A_receiver (see criterion)
     exceeds bf_eps times the scene's reference power (largest
     channel): the power emitted plus the power light sources put on
     the surfaces (lights shoot into the mesh too, and leaves are split
     where their light varies by the same bound):
     relative, so a scene gives the same mesh at any scale or
     brightness.  Default 1e-4. */
  double bf_eps;
  /* Never split an element smaller than area_eps times the total area of
     the scene's surfaces.  Default 1e-4. */
  double area_eps;
  int visibility_rays;  /* k: k x k rays estimate a link's visibility; 4 */
  int max_iterations;   /* gathering sweeps or shots per solve; 1000 */
  /* Stop when the radiosity changed in a sweep (or the unshot power)
     is below residual times the emitted power.  Default 1e-6. */
  double residual;
  int refine_rounds;    /* refine-then-solve rounds; default 6 */
  /* > 0: split every surface into 2^uniform x 2^uniform elements and
     do no refinement (links stay at the elements); default 0. */
  int uniform;
  zr_rad_solver shooting; /* ZR_RAD_SHOOTING or ZR_RAD_GATHERING (0) */
  /* ZR_RAD_CRITERION_BF (default): Hanrahan's BF criterion, B_q F A_p
     with the oracle factor.  ZR_RAD_CRITERION_ERROR: an error
     estimate: the light a link may misplace
     because its factor varies over the receiver (B_q dF A_p), its
     visibility is partial, or its source is uneven (per unit area);
     tighter per element, but many more links. */
  zr_rad_criterion criterion;
  /* 2 (default, library and command line alike): a flat object
     (triangle, polygon, disc, mesh ...) emits from both sides and a
     closed one from its outside, each side by the share of its light
     that gets away from it (the mean over cosine-distributed rays of
     min(1, t / sqrt(area)) for a ray meeting a surface at a distance t
     below twice the finest cell, else 1), so
     POV-Ray's two-sided emitters light the room whichever way they
     are wound and a lamp hung just under a ceiling does not pour
     light into the gap; 1: only the front side, along the outward
     normal (for a triangle (p1 - p0) x (p2 - p0)); 0: both sides at
     full.  Rays that meet an emitting side see its emission whatever
     share it shoots. */
  int one_sided_emission;
  /* How a ray hit reads the solution.  ZR_RAD_LOOKUP_GATHER (default):
     a final gather at
     the hit point over the links its element and the element's
     ancestors gather from, each with the exact point-to-source form
     factor, so the picture has no element seams; ZR_RAD_LOOKUP_SMOOTH:
     the elements' values smoothed over their corners (Gouraud), cheaper
     per pixel.  A saved solution keeps its links and its lookup. */
  zr_rad_lookup lookup;
  /* POV-Ray's radiosity { brightness }: scales the diffuse light the
     solution carries between surfaces where a ray reads it (not the
     surfaces' own emission, not the solve); default 1. */
  double brightness;
  /* Threads that refine and solve (0 or 1: the caller's alone; the
     command line passes +WT).  The solution is the same bytes for any
     number. */
  int threads;
  /* A mesh (mesh, mesh2, height_field) with more faces than this takes
     no part in the solution, with a warning.  Default 0: no limit (a
     mesh's faces link as clusters; 100k faces solve in about 20 CPU
     seconds, bench/radiosity_scale.sh). */
  int max_mesh_faces;
  /* The processes that solve together (NULL: this one alone): each
     member computes its share of the transfer factors, visibility and
     refinement, the members exchange them, and every member ends with
     the same solution bytes as one process alone.  Every member must
     call zr_radiosity_solve with the same scene and parameters. */
  const zr_team *team;
  /* A scene of at least this many surfaces links through volume
     clusters of surfaces (a tree over them; links between clusters
     where the light they carry is below bf_eps), not every two
     surfaces, so its links grow about linearly with its surfaces.
     Default 64; 0 never.  A 25-box furnace keeps B within 1% with
     clusters (tests/test_radiosity.c).  Gathering alone only (not with
     shooting, uniform or a team of more than one member). */
  int cluster_surfaces;
  /* The bounces of light a picture shows: 0, every bounce (the solve
     iterates to convergence); N > 0, at most N, as POV-Ray's radiosity
     recursion_limit N gives them: the gathering solve starts from the
     emission, B_0 = E, and takes B_k = E + rho F B_(k-1) for
     k < N, so a ray hit, which gathers once more, carries light that
     left an emitter (or a light source's lit surface) and bounced at
     most N times; no shooting then (it carries every bounce).  Default 0;
     zr_radiosity_params_init with a scene whose radiosity block is on
     takes its recursion_limit (2 when not written).  Measured against
     povray: tests/test_gi_bounce.sh, bench/gi_bounce.sh. */
  int bounces;
} zr_radiosity_params;

/* Fills p with the defaults above, then takes the settings of the
   scene's global_settings { radiosity { } } block (scene may be NULL):
   brightness, bf_bound, minimum_area, visibility_count, max_iterations
   and residual_bound (zrcube(1), "Radiosity settings"), and bounces
   from recursion_limit (2 when the block is there without it). */
ZR_API void zr_radiosity_params_init(zr_radiosity_params *p,
                                     const zr_scene *scene);

typedef struct zr_radiosity_stats {
  size_t surfaces;    /* exact surfaces of the scene's primitives */
  size_t nodes;       /* quadtree nodes */
  size_t elements;    /* leaves */
  size_t links;
  size_t vertices;
  int refine_rounds;  /* rounds done */
  int iterations;     /* sweeps or shots of the last solve */
  double residual;    /* last change (or unshot power) / emitted power */
  uint64_t visibility_rays;
  /* Energy (mean of the three channels, in scene units^2 * exitance):
     power emitted by all sides, power absorbed by all sides (1 - rho
     of the incident), so a closed scene absorbs what its inner sides
     emit. */
  double emitted_power;
  double absorbed_power;
  /* Sum of F * visibility over all links a leaf side gathers from
     (itself and its ancestors): 1 for a side inside a closed scene.
     Area-weighted mean, minimum and maximum over sides with links. */
  double closure_mean, closure_min, closure_max;
  /* Power the scene's light sources (point, spot, area ...) deliver
     straight onto all sides, the same mean of channels: a closed scene
     absorbs emitted_power (its inner sides') plus light_power. */
  double light_power;
} zr_radiosity_stats;

/* Builds the surfaces, links and solution; errors go through ctx. */
ZR_API zr_status zr_radiosity_solve(zr_context *ctx, const zr_scene *scene,
                                    const zr_radiosity_params *params,
                                    zr_radiosity **out);
ZR_API void zr_radiosity_free(zr_radiosity *rad);
ZR_API void zr_radiosity_get_stats(const zr_radiosity *rad,
                                   zr_radiosity_stats *stats);
/* Writes the solution (header, scene fingerprint, quadtrees and values). */
ZR_API zr_status zr_radiosity_save(zr_context *ctx, const zr_radiosity *rad,
                                   const char *path);
/* Reads a solution saved for this scene; another scene is an error. */
ZR_API zr_status zr_radiosity_load(zr_context *ctx, const zr_scene *scene,
                                   const char *path, zr_radiosity **out);

/* ------------------------------------------------------------------ */
/* Global illumination: the model per scene, the irradiance cache      */
/* ------------------------------------------------------------------ */

/* Which model lights a scene's diffuse interreflection (zrcube(1),
   "Global illumination"). */
typedef enum zr_gi_method {
  ZR_GI_AUTO = 0,      /* chosen per scene by zr_gi_choose() */
  ZR_GI_OFF,           /* POV-Ray's classic ambient term */
  ZR_GI_HIERARCHICAL,  /* zr_radiosity: closed rooms, local emitters */
  ZR_GI_CACHE,         /* zr_gi_cache: POV-Ray's radiosity block */
  ZR_GI_PATH           /* zr_path: the path-traced reference */
} zr_gi_method;

/* "auto", "off", "hierarchical", "cache", "path". */
ZR_API const char *zr_gi_method_name(zr_gi_method m);

/*
 * The model for scene when asked is ZR_GI_AUTO, else asked itself.
 * Without a radiosity block: off.  With one: hierarchical when the
 * scene is lit by emitting surfaces, has no sky (no sky_sphere, a black
 * background) and only kinds of object the hierarchical solver models;
 * the irradiance cache otherwise.  why (may be NULL) receives a
 * sentence saying which test decided.
 */
ZR_API zr_gi_method zr_gi_choose(const zr_scene *scene, zr_gi_method asked,
                                 char *why, size_t why_size);

/*
 * POV-Ray's radiosity block as Ward's irradiance cache (lib/gi/cache.c),
 * with the meaning the POV-Ray 3.7 manual gives each item.  Sky_sphere
 * and background light the scene through the rays that escape.
 */
typedef struct zr_gi_params {
  size_t size;           /* sizeof (zr_gi_params), set by _init */
  int count;             /* rays per new record; 35 */
  int recursion_limit;   /* diffuse bounces; 2 */
  int nearest_count;     /* records a pretrace point wants; 5 */
  double error_bound;    /* 1.8 */
  double low_error_factor; /* error_bound's factor in the pretrace; 0.5 */
  double gray_threshold; /* 0: full colour bleeding */
  double brightness;     /* 1 */
  double minimum_reuse;  /* of the distance from the eye; 0.015 */
  double maximum_reuse;  /* 0.2 */
  double pretrace_start; /* mosaic block, fraction of the image; 0.08 */
  double pretrace_end;   /* 0.04 */
  double adc_bailout;    /* for the sample rays; 0.01 */
  double max_sample;     /* <= 0: samples are not limited (default) */
  int normal;            /* 1: records see normal perturbation; 0 */
  int media;             /* 1: sample rays pass media; 0 */
  int always_sample;     /* 1: the final pass may add records; 0 */
  /* 1: only the sky lights (rays that hit anything bring nothing
     back): the sky light added to a hierarchical solution. */
  int sky_only;
  /* Threads of the pretrace (0 or 1: the caller's alone); the cache is
     the same bytes for any number. */
  int threads;
  /* The processes that pretrace together (NULL: this one alone): the
     cache is the same bytes on every member as one process alone
     makes. */
  const zr_team *team;
  /* The block's save_file and load_file (owned by the scene), NULL
     when not written: the command line loads and saves them. */
  const char *save_file, *load_file;
  /* count's second value: the directions a record's count rays are
     drawn from (about count_pool / count patterns of count rays, one
     per record by its position); 0 or <= count: every record shoots
     the same directions, as POV-Ray's manual says of one value. */
  int count_pool;
  /* nearest_count's second value (adaptive pretrace): from the second
     pretrace pass on, a point served by this many records gathers no
     more; 0: off. */
  int nearest_count_stop;
} zr_gi_params;

/* Whether a sky_sphere or a background that is not black lights the
   scene. */
ZR_API int zr_gi_has_sky(const zr_scene *scene);

/* POV-Ray's defaults, then the scene's radiosity block (scene may be
   NULL). */
ZR_API void zr_gi_params_init(zr_gi_params *p, const zr_scene *scene);

typedef struct zr_gi_cache zr_gi_cache;
struct zr_render_params;

typedef struct zr_gi_stats {
  size_t records;           /* all depths */
  size_t records_depth0;    /* gathered at camera-visible points */
  int pretrace_passes;
  uint64_t sample_rays;     /* rays shot to make records */
} zr_gi_stats;

/* An empty cache for scene (which must outlive it); params may be NULL
   for zr_gi_params_init(scene). */
ZR_API zr_status zr_gi_cache_new(zr_context *ctx, const zr_scene *scene,
                                 const zr_gi_params *params,
                                 zr_gi_cache **out);
/*
 * The pretrace: mosaic passes over an image of render's size, block
 * sizes from pretrace_start down to pretrace_end of the image's larger
 * side (and a last pass over every pixel with always_sample on), each
 * adding the records its pixels ask for.  Pixels of a pass are taken
 * in fixed batches, each batch sees the cache as the batch before left
 * it, and records join in pixel order: the cache is the same bytes for
 * any number of threads, ranks or runs.
 */
ZR_API zr_status zr_gi_cache_pretrace(zr_gi_cache *cache,
                                      const struct zr_render_params *render);
ZR_API void zr_gi_cache_free(zr_gi_cache *cache);
ZR_API void zr_gi_cache_get_stats(const zr_gi_cache *cache,
                                  zr_gi_stats *stats);
/* Writes the records (POV-Ray 3.6's save_file, 3.7's +RFO). */
ZR_API zr_status zr_gi_cache_save(zr_context *ctx, const zr_gi_cache *cache,
                                  const char *path);
/* Reads records saved by zr_gi_cache_save into a new cache for scene;
   a pretrace after it adds only what the file lacks. */
ZR_API zr_status zr_gi_cache_load(zr_context *ctx, const zr_scene *scene,
                                  const zr_gi_params *params,
                                  const char *path, zr_gi_cache **out);

/*
 * The path-traced reference (lib/gi/path.c, zrcube(1) "Path-traced
 * reference"): an unbiased Monte Carlo estimate of the light the other
 * models approximate, with the tracer's materials, light sources, sky
 * and emission, for measuring their error.  Pixel (x, y)'s sample k
 * draws its random numbers from a hash of (seed, pixel, k) only, so an
 * image is the same bytes for any number of ranks and threads, and the
 * samples of a render may be taken in pieces (zr_render_params'
 * path_first_sample): the mean of [0, a) and of [a, b), weighted a and
 * b - a, is the estimate of [0, b).
 */
typedef struct zr_path zr_path;

typedef struct zr_path_params {
  uint32_t seed;      /* mixed into every sample's hash; 0 */
  /* 1 (default): emitting triangles are sampled directly at each
     diffuse bounce (next-event estimation); 0: only the paths that
     happen to hit them see their light.  Both estimate the same image;
     1 has far less noise where emitters are small. */
  int light_sampling;
} zr_path_params;

ZR_API void zr_path_params_init(zr_path_params *p);
/* A path tracer for scene (which must outlive it); params may be NULL
   for zr_path_params_init()'s. */
ZR_API zr_status zr_path_new(zr_context *ctx, const zr_scene *scene,
                             const zr_path_params *params, zr_path **out);
ZR_API void zr_path_free(zr_path *path);
/* How many emitting triangles the tracer samples directly. */
ZR_API size_t zr_path_emitters(const zr_path *path);

/* ------------------------------------------------------------------ */
/* Rendering                                                          */
/* ------------------------------------------------------------------ */

/*
 * The largest image zr_image_new() makes, and so the largest render and
 * the largest image file read: at most ZR_IMAGE_MAX_SIDE pixels a side
 * and ZR_IMAGE_MAX_PIXELS (2^27 = 134217728) pixels in all, 1.5 GiB of
 * floats.
 */
#define ZR_IMAGE_MAX_SIDE 65536
#define ZR_IMAGE_MAX_PIXELS ((size_t)1 << 27)

typedef struct zr_render_params {
  size_t size;          /* sizeof (zr_render_params), set by _init */
  int width;            /* pixels; default 320 */
  int height;           /* pixels; default 240 */
  int antialias;        /* POV-Ray +A: 0 off (default), 1 on */
  double aa_threshold;  /* +A0.3: colour difference that triggers it */
  int aa_depth;         /* +R3: supersampling grid is aa_depth^2 rays */
  int jitter;           /* +J: deterministic jitter of supersamples */
  double jitter_amount; /* default 1.0 */
  /* A solution for this scene to take diffuse interreflection and
     emission from (NULL: none, the default). */
  const zr_radiosity *radiosity;
  int radiosity_only; /* 1: show the radiosity solution alone */
  /* An irradiance cache for this scene (NULL: none, the default): the
     diffuse light arriving at each surface, from the sky too; with a
     radiosity solution, a sky-only cache adds the sky's light. */
  const zr_gi_cache *gi_cache;
  /* +AM: the antialiasing method.  1 (default): a pixel that differs
     from a neighbour gets an aa_depth x aa_depth grid of samples.  2:
     every pixel is the mean of its four corners, and a square whose
     corners differ by more than aa_threshold is split into four, down
     to aa_depth levels ((2^aa_depth + 1)^2 samples at most). */
  int aa_method;
  /* POV-Ray's +Q, 0 to 11 (default 9): below 2 no lighting (each
     surface in its pigment's colour), below 4 no shadows, below 5 area
     lights cast hard shadows, below 6 no transmitted rays and quick_color
     replaces pigments, below 8 no reflected rays, below 9 no media. */
  int quality;
  /* The path-traced reference for this scene (NULL: none, the default;
     not with radiosity or gi_cache): each pixel is the mean of
     path_samples samples spread over its area, numbered from
     path_first_sample; antialiasing is not needed and not done. */
  const zr_path *path;
  int path_samples;      /* default 16 */
  int path_first_sample; /* default 0 */
  /* Threads of zr_render_image() (0 or 1: the caller's alone; default
     1; the pretrace takes zr_gi_params.threads), started per call; the
     image is the same bytes for any number.  zr_render_pixels() runs
     on the calling thread whatever this says: a program with its own
     threads or processes calls it from each. */
  int threads;
  /* Diagnostics, progress and cancel of the calls taking these
     parameters (NULL: none, the default).  It must outlive the call. */
  zr_context *context;
  /* POV-Ray's +UA (Output_Alpha).  0 (default): rgb and centres hold 3
     floats a pixel.  1: 4 floats a pixel, the colour seen with the
     background clear (transparent black, so the colour is premultiplied
     by alpha) and the alpha, 0 where only background shows: in scenes
     of #version 3.7 the background's and sky_sphere's filter and
     transmit make it clear, older scenes have it clear and black; what
     the camera sees through filter and transmit is clear in proportion,
     reflections of the background are not (zrcube(1), "+UA").  Not
     with a path tracer. */
  int alpha;
} zr_render_params;

/* Fills p with POV-Ray's defaults (and the command line's: zrcube(1)
   starts from them). */
ZR_API void zr_render_params_init(zr_render_params *p);

typedef struct zr_render_stats {
  uint64_t camera_rays;
  uint64_t supersample_rays;
  uint64_t reflected_rays;
  uint64_t refracted_rays;
  uint64_t shadow_rays;
  uint64_t supersampled_pixels;
} zr_render_stats;

/* Adds b into a (for combining per-thread statistics). */
ZR_API void zr_render_stats_add(zr_render_stats *a, const zr_render_stats *b);

/*
 * Renders count pixels, pixels[i] = y * width + x, into rgb[3 * i ..] as
 * linear floats in the scene's working colour space (rgb[4 * i ..],
 * colour and alpha, with params->alpha; centres alike).  With centres == NULL
 * this is pass 1 (one ray per pixel centre).  With centres pointing at a
 * complete width * height * 3 image of pass 1, this is the antialiasing
 * pass: pixels whose centre differs from a neighbour's by more than the
 * threshold are supersampled, the others copied.  stats may be NULL; it is
 * added to, not reset.  Thread-safe on one scene.
 */
ZR_API zr_status zr_render_pixels(const zr_scene *scene,
                                  const zr_render_params *params,
                                  const uint32_t *pixels, size_t count,
                                  const float *centres, float *rgb,
                                  zr_render_stats *stats);

/*
 * Both passes over the whole image (rgb: width * height * 3 floats, 4
 * with params->alpha),
 * rows shared among params->threads threads (the caller's among them),
 * with progress (ZR_PHASE_RENDER, rows) and cancel through
 * params->context.  The image is the same bytes for any thread count.
 */
ZR_API zr_status zr_render_image(const zr_scene *scene,
                                 const zr_render_params *params, float *rgb,
                                 zr_render_stats *stats);

/*
 * A picture of the solution's mesh, the check an OpenGL previewer gave:
 * one ray through the centre of every pixel of the scene's camera at
 * params' width and height, each element of the solution shown flat at
 * its radiosity B / pi (light sources' direct light included), other
 * objects and the background black, and the element edges drawn one
 * pixel wide where a pixel's element differs from its right or lower
 * neighbour's: black over bright elements, white over dark ones.  rgb
 * receives width * height * 3 floats, row by row from the top.
 */
ZR_API zr_status zr_radiosity_mesh_image(const zr_radiosity *rad,
                                         const zr_render_params *params,
                                         float *rgb);

/* ------------------------------------------------------------------ */
/* Preview: the scene as triangles, for an OpenGL previewer           */
/* ------------------------------------------------------------------ */

/*
 * A scene drawn without tracing it (zrcube-gtk's previewer): triangles
 * in world space, each with the object's pigment at its centre as
 * colour and its corners' normals, and line segments for what has no
 * triangles yet.  What each kind of object becomes:
 *   - triangles, meshes (mesh, mesh2, smooth_triangle): their faces as
 *     they are (flat normals);
 *   - spheres, boxes, cylinders and cones (with their caps unless
 *     open), tori, discs and polygons (the rectangle around the
 *     polygon, cut to it cell by cell): the exact surfaces of the
 *     hierarchical radiosity solver, sampled on a grid of detail x
 *     detail cells (a flat face detail / 4, at least 1, so its
 *     pigment's pattern shows), two triangles a cell with the
 *     surface's normals at the corners;
 *   - the parts of an intersection, difference or merge: their surfaces
 *     as above, without the cells whose centre the solid does not keep
 *     (so a cut edge is as ragged as a cell);
 *   - infinite planes: their section of the radiosity solver's plane
 *     bounds (the box around every finite object, widened by 10% of its
 *     diagonal) on a grid of 2 detail x 2 detail cells; left out when
 *     the scene has no finite object;
 *   - every other finite object (blob, isosurface, text, prism, lathe,
 *     sor, superellipsoid, height_field, julia_fractal, parametric,
 *     sphere_sweep, ovus, quadric and poly with bounds): the 12 edges of
 *     its world bounding box, as line segments in its pigment's colour;
 *   - unbounded objects other than planes: left out (counted).
 * The camera is the scene's after all its modifiers (POV-Ray's camera
 * vectors): a ray through the image point (u, v) in [-0.5, 0.5]^2 has
 * the direction direction + u right + v up from location.  Projections
 * other than perspective are reported by kind for the caller to say it
 * draws them as perspective.
 */
typedef struct zr_preview zr_preview;

typedef struct zr_preview_camera {
  double location[3];
  double direction[3];
  double up[3];
  double right[3];
  double sky[3];
  /* 1 perspective (what a previewer draws exactly), 0 any other
     projection (orthographic, fisheye, panoramic ...). */
  int perspective;
  /* 1 when the scene has a camera block, 0 for POV-Ray's default. */
  int given;
} zr_preview_camera;

typedef struct zr_preview_info {
  size_t triangles;
  size_t lines;
  size_t objects_as_triangles; /* primitives with triangles */
  size_t objects_as_boxes;     /* primitives drawn as bounding boxes */
  size_t objects_left_out;     /* unbounded, or no area */
  /* The box around every finite primitive (lo > hi when none). */
  double lo[3], hi[3];
} zr_preview_info;

/*
 * Makes the preview of scene with detail cells a side on curved
 * surfaces (0: the default, 24; at most 256; ZR_EINVAL outside).
 * ZR_ENOMEM (with a message through ctx, which may be NULL) when the
 * triangles do not fit.
 */
ZR_API zr_status zr_scene_preview(zr_context *ctx, const zr_scene *scene,
                                  int detail, zr_preview **out);
ZR_API void zr_preview_free(zr_preview *preview);
ZR_API void zr_preview_get_info(const zr_preview *preview,
                                zr_preview_info *info);
ZR_API void zr_preview_get_camera(const zr_preview *preview,
                                  zr_preview_camera *camera);
/*
 * The triangles: *xyz receives 9 floats a triangle (its corners, world
 * space), *normal 9 (a unit normal a corner), *rgb 3 (linear colour in
 * the scene's working space, filter and transmit left out).  Any of the
 * pointers may be NULL.  Owned by the preview.  Returns the count.
 */
ZR_API size_t zr_preview_triangles(const zr_preview *preview,
                                   const float **xyz, const float **normal,
                                   const float **rgb);
/* The line segments: 6 floats a segment in *xyz, 3 in *rgb. */
ZR_API size_t zr_preview_lines(const zr_preview *preview, const float **xyz,
                               const float **rgb);

/* ------------------------------------------------------------------ */
/* Images                                                             */
/* ------------------------------------------------------------------ */

typedef enum zr_image_format {
  ZR_FORMAT_AUTO = 0, /* from the file name's extension */
  ZR_FORMAT_PNG8,
  ZR_FORMAT_PNG16,
  ZR_FORMAT_PPM,      /* binary P6, 8 bit */
  ZR_FORMAT_PFM,      /* linear float, no gamma */
  ZR_FORMAT_JPEG,     /* baseline, 4:4:4, quality 85 unless set */
  ZR_FORMAT_TGA,      /* uncompressed, 24 bit (32 with alpha) */
  ZR_FORMAT_TGA_RLE,  /* run-length encoded, 24 bit (32 with alpha) */
  ZR_FORMAT_HDR,      /* Radiance RGBE, linear, run-length encoded */
  ZR_FORMAT_EXR,      /* OpenEXR, half floats, linear (if built with it) */
  ZR_FORMAT_BMP       /* Windows bitmap, 24 bit (32 with alpha) */
} zr_image_format;

/* An RGB image of linear floats, rows top to bottom. */
typedef struct zr_image zr_image;

ZR_API zr_status zr_image_new(int width, int height, zr_image **out);
ZR_API void zr_image_free(zr_image *image);
ZR_API int zr_image_width(const zr_image *image);
ZR_API int zr_image_height(const zr_image *image);
/* width * height * 3 floats, owned by the image. */
ZR_API float *zr_image_pixels(zr_image *image);
ZR_API const float *zr_image_pixels_const(const zr_image *image);

/*
 * Reads a PNG, JPEG, GIF, TGA, BMP, TIFF, PPM/PGM (P3/P5/P6), PFM,
 * Radiance HDR or OpenEXR file; 8 and 16 bit files
 * are decoded from their gamma (sRGB unless the file says otherwise) into
 * linear floats.  A PNG's alpha (an alpha channel or tRNS transparency)
 * comes with it, straight, as zr_image_alpha's; other files' alpha is
 * not read.  Errors are reported through ctx (which may be NULL).
 */
ZR_API zr_status zr_image_read(zr_context *ctx, const char *path,
                               zr_image **out);

/*
 * Writes the image.  8 and 16 bit formats are encoded with the sRGB
 * transfer function after the working gamma is undone:
 * stored = srgb(value ^ assumed_gamma); PFM stores linear values.
 * Pass assumed_gamma 1.0 for linear input.
 */
ZR_API zr_status zr_image_write(zr_context *ctx, const zr_image *image,
                                const char *path, zr_image_format format,
                                double assumed_gamma);

/* The format a file name asks for (ZR_FORMAT_AUTO when unknown). */
ZR_API zr_image_format zr_image_format_from_name(const char *path);

/*
 * An alpha channel, one float a pixel in [0, 1] (1 opaque), rows top to
 * bottom, made and owned by the image (all 1 when made).  PNG, TGA, BMP
 * and OpenEXR files are written with it when the image has one (PNG
 * RGBA, TGA and BMP 32 bit); the other formats leave it out.  Colours
 * stay unmultiplied (OpenEXR files store them premultiplied, as that
 * format and povray do).
 */
ZR_API zr_status zr_image_add_alpha(zr_image *image);
/* The alpha channel, or NULL when the image has none. */
ZR_API float *zr_image_alpha(zr_image *image);

/*
 * An image still being made (rows arriving from a renderer while it is
 * written): every writer (zr_image_write, _save, _encode, _write_file)
 * calls wait(rows, user) before it reads row rows - 1 (PNG, row after
 * row) or before it reads any row (the other formats, with rows the
 * height), and reads on when wait returns 0, the rows 0 .. rows - 1 and
 * their alpha being final; a nonzero return fails the write with
 * ZR_ECANCELLED.  wait runs on the writing thread.  NULL: no waiting
 * (the default).
 */
typedef int (*zr_image_rows_fn)(int rows, void *user);
ZR_API void zr_image_set_rows_wait(zr_image *image, zr_image_rows_fn wait,
                                   void *user);

/* How an image is encoded: zr_image_encoding_init() gives the defaults. */
typedef struct zr_image_encoding {
  zr_image_format format; /* not ZR_FORMAT_AUTO */
  double assumed_gamma;   /* as zr_image_write's; default 1.0 */
  int quality;            /* JPEG quality 2 .. 100; 0 or 1: 85 (default) */
  int alpha;              /* 1 (default): write the alpha channel if any */
  /* POV-Ray's File_Gamma for the 8 and 16 bit formats: 0 (default) the
     sRGB transfer; G > 0 codes pre-corrected for a display of gamma G,
     linear^(1/G) (PNG files then carry gAMA 1/G).  Pass
     zr_scene_file_gamma() when it is not 0. */
  double file_gamma;
} zr_image_encoding;

ZR_API void zr_image_encoding_init(zr_image_encoding *e,
                                   zr_image_format format);

/*
 * Encodes the image into a new buffer of *size bytes, *bytes (release it
 * with free()).  On failure *bytes is NULL and *size 0.
 */
ZR_API zr_status zr_image_encode(zr_context *ctx, const zr_image *image,
                                 const zr_image_encoding *e,
                                 unsigned char **bytes, size_t *size);

/*
 * Encodes the image to an open stream at its current position (standard
 * output, a pipe, a socket): the stream is flushed, not closed.
 */
ZR_API zr_status zr_image_write_file(zr_context *ctx, const zr_image *image,
                                     const zr_image_encoding *e,
                                     FILE *stream);

/* zr_image_write with every encoding setting (e->format may be AUTO). */
ZR_API zr_status zr_image_save(zr_context *ctx, const zr_image *image,
                               const char *path,
                               const zr_image_encoding *e);

/* 1 when this build of the library writes and reads the format. */
ZR_API int zr_image_format_supported(zr_image_format format);

/* The scene's assumed_gamma (1.0 when the scene does not set it; 2.2
   in a legacy scene, see zr_scene_file_gamma). */
ZR_API double zr_scene_assumed_gamma(const zr_scene *scene);

/*
 * The file gamma the scene imposes, 0 when it leaves it to the caller
 * (zr_image_encoding's file_gamma, sRGB by default).  A legacy scene
 * (neither assumed_gamma nor a #version 3.7 in force at its end) has
 * POV-Ray's gamma correction turned off ("Gamma in Legacy Scenes"): its
 * colours are written as they are, whatever File_Gamma says, which is
 * assumed_gamma 2.2 written with file gamma 2.2.
 */
ZR_API double zr_scene_file_gamma(const zr_scene *scene);

/*
 * The encoding POV-Ray writes the scene's pictures with:
 * zr_image_encoding_init(e, format), the scene's assumed gamma
 * (zr_scene_assumed_gamma) and the file gamma it imposes
 * (zr_scene_file_gamma; 0, sRGB, when it leaves it to the caller, who
 * may then set e->file_gamma).
 */
ZR_API void zr_scene_image_encoding(const zr_scene *scene,
                                    zr_image_format format,
                                    zr_image_encoding *e);

#ifdef __cplusplus
}
#endif

#endif /* ZRCUBE_H */
