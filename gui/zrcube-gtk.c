/*
 * zrcube-gtk - the GTK 4 front end: opens a scene, previews it with
 * OpenGL from the scene's camera, renders it with libzrcube on a worker
 * thread, and saves the picture.
 *
 * The preview draws what zr_scene_preview gives (include/zrcube.h):
 * triangles in each object's pigment and the bounding-box edges of the
 * objects that have no triangles yet.  Its projection is the scene's
 * own camera, exactly: POV-Ray sends the ray of image point (u, v),
 * both in [-0.5, 0.5], along direction + u right + v up from location,
 * so a world point p lies at (u, v) = (a / c, b / c) where (a, b, c)
 * solves [right up direction] (a, b, c) = p - location.  The clip
 * coordinates (2a, 2b, depth, c) give that after the divide by w, and
 * hold for non-orthogonal and left-handed camera vectors alike.  The
 * picture keeps the render's aspect ratio inside the widget (bars
 * around it), so the preview lines up with the render.
 *
 * Mouse drag orbits the camera about the middle of the scene's bounds
 * (sideways about the sky vector, up and down about the right vector),
 * the scroll wheel moves it nearer or farther, and the key r (or Home)
 * goes back to the scene's camera.  The library's rules for contexts
 * are kept: the context that parsed a scene is used by one thread at a
 * time (the worker while it renders, the main loop otherwise), and only
 * zr_context_cancel() crosses threads.
 *
 * --screenshot FILE draws the preview once, reads the picture back from
 * GtkGLArea's framebuffer and writes it as PNG, then quits: the test
 * (tests/test_gtk.sh) runs that under xvfb-run and checks where the
 * objects land.  --render FILE presses Render, and when the worker is
 * done writes what Save would, then quits: the test compares it with
 * zrcube's picture of the scene, byte for byte.
 */
#include <epoxy/gl.h>
#include <gtk/gtk.h>
#include <math.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zrcube.h"

/* The render size when none is given: zrcube's own default. */
#define DEFAULT_WIDTH 320
#define DEFAULT_HEIGHT 240

typedef struct view {
  double location[3], direction[3], up[3], right[3];
} view;

typedef struct app {
  GtkApplication *gtk;
  GtkWidget *window, *gl_area, *stack, *picture, *message, *status;
  GtkWidget *progress, *open_button, *render_button, *cancel_button;
  GtkWidget *save_button;
  /* Command-line settings. */
  char *scene_path;
  char *screenshot_path;
  char *render_path; /* --render: render, save here, quit */
  char *load_path;   /* the scene being or last loaded */
  zr_status load_status;
  /* What the load's worker made, taken over by load_done: the main
     loop draws scene and preview meanwhile, so the worker never
     writes those. */
  zr_scene *loaded_scene;
  zr_preview *loaded_preview;
  int width, height;
  int exit_status;
  /* --orbit: the view a drag and scroll would give, applied after the
     scene loads (yaw and pitch in degrees, zoom a factor). */
  double orbit[3];
  bool have_orbit;
  /* The scene and what it draws. */
  zr_context *ctx;
  zr_scene *scene;
  zr_preview *preview;
  zr_preview_camera scene_camera;
  double centre[3], radius;
  GString *diagnostics;
  /* Orbit state, relative to the scene's camera. */
  double yaw, pitch, zoom, drag_yaw, drag_pitch;
  /* GL objects (0 until the area is realized). */
  GLuint program, vao, vbo[3], line_vao, line_vbo[2];
  GLint u_clip, u_lit, u_eye;
  size_t gl_tris, gl_lines;
  gboolean gl_dirty;
  /* The render on the worker thread. */
  GThread *worker;
  zr_image *image;
  zr_status render_status;
  atomic_ullong done, total;
  atomic_int progress_queued;
  unsigned char *png;
  size_t png_size;
} app;

/* ---- vectors ---- */

static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void normalise3(double a[3]) {
  double l = sqrt(dot3(a, a));
  if (l > 0.0)
    for (int k = 0; k < 3; k++)
      a[k] /= l;
}

/* v turned by angle about the unit axis (Rodrigues' formula). */
static void rotate3(double v[3], const double axis[3], double angle) {
  double c = cos(angle), s = sin(angle), d = dot3(axis, v);
  double x[3] = {axis[1] * v[2] - axis[2] * v[1],
                 axis[2] * v[0] - axis[0] * v[2],
                 axis[0] * v[1] - axis[1] * v[0]};
  for (int k = 0; k < 3; k++)
    v[k] = v[k] * c + x[k] * s + axis[k] * d * (1.0 - c);
}

/* The camera as the orbit has moved it. */
static void current_view(const app *a, view *v) {
  const zr_preview_camera *c = &a->scene_camera;
  memcpy(v->location, c->location, sizeof v->location);
  memcpy(v->direction, c->direction, sizeof v->direction);
  memcpy(v->up, c->up, sizeof v->up);
  memcpy(v->right, c->right, sizeof v->right);
  double sky[3] = {c->sky[0], c->sky[1], c->sky[2]};
  normalise3(sky);
  if (dot3(sky, sky) == 0.0)
    sky[1] = 1.0;
  double arm[3];
  for (int k = 0; k < 3; k++)
    arm[k] = v->location[k] - a->centre[k];
  double *turned[4] = {arm, v->direction, v->up, v->right};
  for (int i = 0; i < 4; i++)
    rotate3(turned[i], sky, a->yaw);
  double axis[3] = {v->right[0], v->right[1], v->right[2]};
  normalise3(axis);
  for (int i = 0; i < 4; i++)
    rotate3(turned[i], axis, a->pitch);
  for (int k = 0; k < 3; k++)
    v->location[k] = a->centre[k] + arm[k] * a->zoom;
}

/*
 * The clip matrix of view v (column-major, as GL takes it): the inverse
 * of [right up direction] maps p - location to (a, b, c); the clip
 * point is (2a, 2b, A c + B, c) with A and B putting c = near and
 * c = far (in units of |direction| along it) at depths -1 and 1.
 */
static bool clip_matrix(const view *v, double near, double far,
                        float out[16]) {
  const double *r = v->right, *u = v->up, *d = v->direction;
  /* Rows of the inverse: the cross products over the determinant. */
  double inv[3][3] = {
      {u[1] * d[2] - u[2] * d[1], u[2] * d[0] - u[0] * d[2],
       u[0] * d[1] - u[1] * d[0]},
      {d[1] * r[2] - d[2] * r[1], d[2] * r[0] - d[0] * r[2],
       d[0] * r[1] - d[1] * r[0]},
      {r[1] * u[2] - r[2] * u[1], r[2] * u[0] - r[0] * u[2],
       r[0] * u[1] - r[1] * u[0]}};
  double det = dot3(r, inv[0]);
  if (!(fabs(det) > 1e-300))
    return false;
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++)
      inv[i][k] /= det;
  double A = (far + near) / (far - near), B = -2.0 * far * near / (far - near);
  double rows[4][4];
  for (int k = 0; k < 3; k++) {
    rows[0][k] = 2.0 * inv[0][k];
    rows[1][k] = 2.0 * inv[1][k];
    rows[2][k] = A * inv[2][k];
    rows[3][k] = inv[2][k];
  }
  for (int i = 0; i < 4; i++)
    rows[i][3] = -(rows[i][0] * v->location[0] + rows[i][1] * v->location[1] +
                   rows[i][2] * v->location[2]);
  rows[2][3] += B;
  for (int i = 0; i < 4; i++)
    for (int k = 0; k < 4; k++)
      out[4 * k + i] = (float)rows[i][k];
  return true;
}

/* ---- GL ---- */

static const char *vertex_source =
    "#version 150 core\n"
    "in vec3 position;\n"
    "in vec3 normal;\n"
    "in vec3 colour;\n"
    "uniform mat4 clip;\n"
    "uniform vec3 eye;\n"
    "uniform float lit;\n"
    "out vec3 shade;\n"
    "void main() {\n"
    "  gl_Position = clip * vec4(position, 1.0);\n"
    /* A head light: surfaces facing the eye are brightest, from either
       side (the preview has no back faces). */
    "  vec3 to_eye = normalize(eye - position);\n"
    "  float f = lit > 0.5 ? 0.25 + 0.75 * abs(dot(normalize(normal),"
    " to_eye)) : 1.0;\n"
    "  shade = colour * f;\n"
    "}\n";

static const char *fragment_source =
    "#version 150 core\n"
    "in vec3 shade;\n"
    "out vec4 frag;\n"
    "void main() {\n"
    /* The colours are linear: shown with the sRGB curve's gamma. */
    "  frag = vec4(pow(clamp(shade, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);\n"
    "}\n";

static GLuint compile(GLenum kind, const char *source, GString *log) {
  GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &source, NULL);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char text[1024];
    glGetShaderInfoLog(s, sizeof text, NULL, text);
    g_string_append_printf(log, "shader: %s\n", text);
    glDeleteShader(s);
    return 0;
  }
  return s;
}

static gboolean quit_idle(gpointer data);

static void show_message(app *a, const char *text, gboolean error) {
  gtk_label_set_text(GTK_LABEL(a->message), text);
  if (error)
    gtk_widget_add_css_class(a->message, "error");
  else
    gtk_widget_remove_css_class(a->message, "error");
  if (a->screenshot_path != NULL && error && *text)
    fprintf(stderr, "zrcube-gtk: %s", text);
}

static void on_realize(GtkGLArea *area, app *a) {
  gtk_gl_area_make_current(area);
  if (gtk_gl_area_get_error(area) != NULL) {
    char *m = g_strdup_printf("OpenGL: %s\n",
                              gtk_gl_area_get_error(area)->message);
    show_message(a, m, TRUE);
    g_free(m);
    /* A machine without OpenGL: --screenshot says so by its status (3),
       which the test takes for "cannot run here", not for a failure. */
    if (a->screenshot_path != NULL) {
      a->exit_status = 3;
      g_free(a->screenshot_path);
      a->screenshot_path = NULL;
      g_idle_add(quit_idle, a);
    }
    return;
  }
  GString *log = g_string_new(NULL);
  GLuint vs = compile(GL_VERTEX_SHADER, vertex_source, log);
  GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source, log);
  if (vs && fs) {
    a->program = glCreateProgram();
    glAttachShader(a->program, vs);
    glAttachShader(a->program, fs);
    glBindAttribLocation(a->program, 0, "position");
    glBindAttribLocation(a->program, 1, "normal");
    glBindAttribLocation(a->program, 2, "colour");
    glLinkProgram(a->program);
    GLint ok = 0;
    glGetProgramiv(a->program, GL_LINK_STATUS, &ok);
    if (!ok) {
      char text[1024];
      glGetProgramInfoLog(a->program, sizeof text, NULL, text);
      g_string_append_printf(log, "shader program: %s\n", text);
      glDeleteProgram(a->program);
      a->program = 0;
    }
  }
  if (vs)
    glDeleteShader(vs);
  if (fs)
    glDeleteShader(fs);
  if (a->program == 0) {
    show_message(a, log->str, TRUE);
    g_string_free(log, TRUE);
    if (a->screenshot_path != NULL) {
      a->exit_status = 1;
      g_free(a->screenshot_path);
      a->screenshot_path = NULL;
      g_idle_add(quit_idle, a);
    }
    return;
  }
  g_string_free(log, TRUE);
  a->u_clip = glGetUniformLocation(a->program, "clip");
  a->u_eye = glGetUniformLocation(a->program, "eye");
  a->u_lit = glGetUniformLocation(a->program, "lit");
  glGenVertexArrays(1, &a->vao);
  glGenBuffers(3, a->vbo);
  glGenVertexArrays(1, &a->line_vao);
  glGenBuffers(2, a->line_vbo);
  a->gl_dirty = TRUE;
}

static void on_unrealize(GtkGLArea *area, app *a) {
  gtk_gl_area_make_current(area);
  if (gtk_gl_area_get_error(area) != NULL || a->program == 0)
    return;
  glDeleteBuffers(3, a->vbo);
  glDeleteBuffers(2, a->line_vbo);
  glDeleteVertexArrays(1, &a->vao);
  glDeleteVertexArrays(1, &a->line_vao);
  glDeleteProgram(a->program);
  a->program = 0;
}

/* Copies the preview's triangles and lines into the buffers (each
   triangle's colour on its three corners). */
static void upload(app *a) {
  a->gl_dirty = FALSE;
  a->gl_tris = a->gl_lines = 0;
  if (a->preview == NULL)
    return;
  const float *xyz, *normal, *rgb;
  size_t n = zr_preview_triangles(a->preview, &xyz, &normal, &rgb);
  float *corner_rgb = g_malloc_n(n * 9 + 1, sizeof(float));
  for (size_t t = 0; t < n; t++)
    for (int k = 0; k < 3; k++)
      memcpy(&corner_rgb[9 * t + 3 * k], &rgb[3 * t], 3 * sizeof(float));
  glBindVertexArray(a->vao);
  const float *data[3] = {xyz, normal, corner_rgb};
  for (int i = 0; i < 3; i++) {
    glBindBuffer(GL_ARRAY_BUFFER, a->vbo[i]);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(n * 9 * sizeof(float)),
                 n ? data[i] : NULL, GL_STATIC_DRAW);
    glEnableVertexAttribArray((GLuint)i);
    glVertexAttribPointer((GLuint)i, 3, GL_FLOAT, GL_FALSE, 0, NULL);
  }
  g_free(corner_rgb);
  a->gl_tris = n;
  size_t m = zr_preview_lines(a->preview, &xyz, &rgb);
  float *end_rgb = g_malloc_n(m * 6 + 1, sizeof(float));
  for (size_t l = 0; l < m; l++)
    for (int k = 0; k < 2; k++)
      memcpy(&end_rgb[6 * l + 3 * k], &rgb[3 * l], 3 * sizeof(float));
  glBindVertexArray(a->line_vao);
  glBindBuffer(GL_ARRAY_BUFFER, a->line_vbo[0]);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(m * 6 * sizeof(float)),
               m ? xyz : NULL, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, NULL);
  /* Lines are not lit: a constant normal keeps the attribute defined. */
  glDisableVertexAttribArray(1);
  glVertexAttrib3f(1, 0.0f, 0.0f, 1.0f);
  glBindBuffer(GL_ARRAY_BUFFER, a->line_vbo[1]);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(m * 6 * sizeof(float)),
               m ? end_rgb : NULL, GL_STATIC_DRAW);
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 0, NULL);
  g_free(end_rgb);
  a->gl_lines = m;
  glBindVertexArray(0);
}

/* The picture's place in a widget of w x h pixels: the render's aspect
   ratio, centred. */
static void viewport(const app *a, int w, int h, int box[4]) {
  double want = (double)a->width / a->height;
  int vw = w, vh = h;
  if ((double)w / h > want)
    vw = (int)lround(h * want);
  else
    vh = (int)lround(w / want);
  if (vw < 1)
    vw = 1;
  if (vh < 1)
    vh = 1;
  box[0] = (w - vw) / 2;
  box[1] = (h - vh) / 2;
  box[2] = vw;
  box[3] = vh;
}

static void write_screenshot(app *a, const int box[4]);

static gboolean on_render(GtkGLArea *area, GdkGLContext *context, app *a) {
  (void)context;
  if (a->program == 0)
    return TRUE;
  if (a->gl_dirty)
    upload(a);
  int scale = gtk_widget_get_scale_factor(GTK_WIDGET(area));
  int w = gtk_widget_get_width(GTK_WIDGET(area)) * scale;
  int h = gtk_widget_get_height(GTK_WIDGET(area)) * scale;
  int box[4];
  viewport(a, w, h, box);
  glViewport(0, 0, w, h);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glViewport(box[0], box[1], box[2], box[3]);
  glEnable(GL_SCISSOR_TEST);
  glScissor(box[0], box[1], box[2], box[3]);
  /* The picture's own background: a dark grey, so black objects show. */
  glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  if (a->preview != NULL) {
    view v;
    current_view(a, &v);
    /* Near and far from the bounds, in units of |direction|. */
    double dl = sqrt(dot3(v.direction, v.direction));
    double to_centre[3];
    for (int k = 0; k < 3; k++)
      to_centre[k] = a->centre[k] - v.location[k];
    double dist = sqrt(dot3(to_centre, to_centre));
    double far = (dist + 2.0 * a->radius) / dl;
    double near = far * 1e-4;
    float clip[16];
    if (clip_matrix(&v, near, far, clip)) {
      glEnable(GL_DEPTH_TEST);
      glUseProgram(a->program);
      glUniformMatrix4fv(a->u_clip, 1, GL_FALSE, clip);
      glUniform3f(a->u_eye, (float)v.location[0], (float)v.location[1],
                  (float)v.location[2]);
      glUniform1f(a->u_lit, 1.0f);
      glBindVertexArray(a->vao);
      glDrawArrays(GL_TRIANGLES, 0, (GLsizei)(3 * a->gl_tris));
      glUniform1f(a->u_lit, 0.0f);
      glBindVertexArray(a->line_vao);
      glDrawArrays(GL_LINES, 0, (GLsizei)(2 * a->gl_lines));
      glBindVertexArray(0);
      glUseProgram(0);
    }
  }
  glFlush();
  if (a->screenshot_path != NULL && a->preview != NULL)
    write_screenshot(a, box);
  return TRUE;
}

/* ---- screenshot ---- */

static gboolean quit_idle(gpointer data) {
  app *a = data;
  g_application_quit(G_APPLICATION(a->gtk));
  return G_SOURCE_REMOVE;
}

static void write_screenshot(app *a, const int box[4]) {
  int w = box[2], h = box[3];
  size_t stride = (size_t)w * 4;
  guchar *pixels = g_malloc(stride * (size_t)h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(box[0], box[1], w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  /* GL's rows run bottom up; a PNG's top down. */
  guchar *row = g_malloc(stride);
  for (int y = 0; y < h / 2; y++) {
    memcpy(row, pixels + stride * (size_t)y, stride);
    memcpy(pixels + stride * (size_t)y, pixels + stride * (size_t)(h - 1 - y),
           stride);
    memcpy(pixels + stride * (size_t)(h - 1 - y), row, stride);
  }
  g_free(row);
  GBytes *bytes = g_bytes_new_take(pixels, stride * (size_t)h);
  GdkTexture *tex = gdk_memory_texture_new(w, h, GDK_MEMORY_R8G8B8A8, bytes,
                                           stride);
  g_bytes_unref(bytes);
  if (!gdk_texture_save_to_png(tex, a->screenshot_path)) {
    fprintf(stderr, "zrcube-gtk: cannot write %s\n", a->screenshot_path);
    a->exit_status = 1;
  } else {
    a->exit_status = 0;
  }
  g_object_unref(tex);
  g_free(a->screenshot_path);
  a->screenshot_path = NULL;
  g_idle_add(quit_idle, a);
}

static gboolean screenshot_timeout(gpointer data) {
  app *a = data;
  if (a->screenshot_path != NULL) {
    fprintf(stderr, "zrcube-gtk: the preview was not drawn within 60 "
                    "seconds; no screenshot\n");
    a->exit_status = 1;
    g_application_quit(G_APPLICATION(a->gtk));
  }
  return G_SOURCE_REMOVE;
}

/* ---- scenes ---- */

static void on_diag(const zr_diag *d, void *user) {
  app *a = user;
  if (d->level == ZR_DIAG_ERROR || d->level == ZR_DIAG_WARNING ||
      d->level == ZR_DIAG_NOTE)
    g_string_append(a->diagnostics, d->text);
}

static void update_buttons(app *a) {
  gboolean busy = a->worker != NULL;
  gtk_widget_set_sensitive(a->open_button, !busy);
  gtk_widget_set_sensitive(a->render_button, !busy && a->scene != NULL);
  gtk_widget_set_sensitive(a->cancel_button, busy);
  gtk_widget_set_sensitive(a->save_button, !busy && a->png != NULL);
}

static void reset_view(app *a) {
  a->yaw = a->pitch = 0.0;
  a->zoom = 1.0;
  gtk_gl_area_queue_render(GTK_GL_AREA(a->gl_area));
}

static void on_render_clicked(GtkButton *button, app *a);
static gboolean load_done(gpointer data);

/* The worker's half of a load: parse and preview, nothing of GTK. */
static gpointer load_thread(gpointer data) {
  app *a = data;
  zr_status st = zr_scene_parse_file(a->ctx, a->load_path, &a->loaded_scene);
  if (st == ZR_OK)
    st = zr_scene_preview(a->ctx, a->loaded_scene, 0, &a->loaded_preview);
  a->load_status = st;
  g_idle_add(load_done, a);
  return NULL;
}

/*
 * Parses path into a new scene and preview, replacing the old ones, on
 * the worker thread (a large scene takes seconds to parse and preview:
 * 9 s for the corpus' spacecraft cell_comparison.pov, and the window
 * must keep drawing); load_done shows the result.  Cancel stops the
 * parse.
 */
static void load_scene(app *a, const char *path) {
  if (a->worker != NULL)
    return;
  zr_preview_free(a->preview);
  a->preview = NULL;
  zr_scene_free(a->scene);
  a->scene = NULL;
  zr_context_free(a->ctx);
  a->ctx = NULL;
  free(a->png);
  a->png = NULL;
  a->png_size = 0;
  g_string_truncate(a->diagnostics, 0);
  g_free(a->load_path);
  a->load_path = g_strdup(path);
  a->gl_dirty = TRUE;
  gtk_gl_area_queue_render(GTK_GL_AREA(a->gl_area));
  zr_status st = zr_context_new(&a->ctx);
  if (st == ZR_OK) {
    zr_context_set_diag(a->ctx, on_diag, a);
    st = zr_context_set_render_size(a->ctx, a->width, a->height);
  }
  if (st != ZR_OK) {
    a->load_status = st;
    load_done(a);
    return;
  }
  char *title = g_path_get_basename(path);
  char *s = g_strdup_printf("%s: parsing ...", title);
  gtk_label_set_text(GTK_LABEL(a->status), s);
  g_free(s);
  g_free(title);
  show_message(a, "", FALSE);
  a->worker = g_thread_new("load", load_thread, a);
  update_buttons(a);
}

/* The main loop's half: on failure shows the messages (file:line:column)
   and keeps nothing; on success the preview and its status line. */
static gboolean load_done(gpointer data) {
  app *a = data;
  if (a->worker != NULL) {
    g_thread_join(a->worker);
    a->worker = NULL;
  }
  if (a->ctx != NULL)
    zr_context_cancel(a->ctx, 0);
  a->scene = a->loaded_scene;
  a->preview = a->loaded_preview;
  a->loaded_scene = NULL;
  a->loaded_preview = NULL;
  zr_status st = a->load_status;
  const char *path = a->load_path;
  char *title = g_path_get_basename(path);
  gtk_window_set_title(GTK_WINDOW(a->window), title);
  if (st != ZR_OK) {
    if (a->diagnostics->len == 0)
      g_string_printf(a->diagnostics, "%s: %s\n", path, zr_status_str(st));
    show_message(a, a->diagnostics->str, st != ZR_ECANCELLED);
    gtk_label_set_text(GTK_LABEL(a->status), "no scene");
    zr_preview_free(a->preview);
    a->preview = NULL;
    zr_scene_free(a->scene);
    a->scene = NULL;
    if (a->screenshot_path != NULL || a->render_path != NULL) {
      if (a->render_path != NULL)
        fprintf(stderr, "zrcube-gtk: %s", a->diagnostics->str);
      a->exit_status = 1;
      g_idle_add(quit_idle, a);
    }
  } else {
    show_message(a, a->diagnostics->str, FALSE);
    zr_preview_get_camera(a->preview, &a->scene_camera);
    zr_preview_info info;
    zr_preview_get_info(a->preview, &info);
    /* The orbit's centre: the middle of the finite objects (the point
       straight ahead when there are none). */
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) {
      if (info.lo[k] <= info.hi[k]) {
        a->centre[k] = 0.5 * (info.lo[k] + info.hi[k]);
        r2 += 0.25 * (info.hi[k] - info.lo[k]) * (info.hi[k] - info.lo[k]);
      } else {
        a->centre[k] = a->scene_camera.location[k] +
                       a->scene_camera.direction[k];
      }
    }
    a->radius = sqrt(r2) > 0.0 ? sqrt(r2) : 1.0;
    char *s = g_strdup_printf(
        "%s: %zu triangles, %zu box edges (%zu objects as triangles, %zu as "
        "bounding boxes, %zu left out)%s",
        title, info.triangles, info.lines, info.objects_as_triangles,
        info.objects_as_boxes, info.objects_left_out,
        a->scene_camera.perspective
            ? ""
            : "; the camera's projection is drawn as a perspective one");
    gtk_label_set_text(GTK_LABEL(a->status), s);
    g_free(s);
  }
  g_free(title);
  a->gl_dirty = TRUE;
  reset_view(a);
  if (a->have_orbit) {
    a->yaw = a->orbit[0] * M_PI / 180.0;
    a->pitch = a->orbit[1] * M_PI / 180.0;
    a->zoom = a->orbit[2];
  }
  update_buttons(a);
  if (a->render_path != NULL && a->scene != NULL)
    on_render_clicked(NULL, a);
  return G_SOURCE_REMOVE;
}

/* ---- rendering on a worker thread ---- */

static gboolean progress_idle(gpointer data) {
  app *a = data;
  atomic_store(&a->progress_queued, 0);
  unsigned long long done = atomic_load(&a->done);
  unsigned long long total = atomic_load(&a->total);
  if (total > 0)
    gtk_progress_bar_set_fraction(GTK_PROGRESS_BAR(a->progress),
                                  (double)done / (double)total);
  return G_SOURCE_REMOVE;
}

static int on_progress(const zr_progress *p, void *user) {
  app *a = user;
  if (p->phase != ZR_PHASE_RENDER)
    return 0;
  atomic_store(&a->done, p->done);
  atomic_store(&a->total, p->total);
  if (atomic_exchange(&a->progress_queued, 1) == 0)
    g_idle_add(progress_idle, a);
  return 0;
}

static gboolean render_done(gpointer data) {
  app *a = data;
  g_thread_join(a->worker);
  a->worker = NULL;
  zr_context_cancel(a->ctx, 0);
  zr_context_set_progress(a->ctx, NULL, NULL);
  if (a->render_status == ZR_OK) {
    zr_image_encoding e;
    zr_scene_image_encoding(a->scene, ZR_FORMAT_PNG8, &e);
    zr_status st = zr_image_encode(a->ctx, a->image, &e, &a->png,
                                   &a->png_size);
    if (st == ZR_OK) {
      GBytes *bytes = g_bytes_new(a->png, a->png_size);
      GError *err = NULL;
      GdkTexture *tex = gdk_texture_new_from_bytes(bytes, &err);
      g_bytes_unref(bytes);
      if (tex != NULL) {
        gtk_picture_set_paintable(GTK_PICTURE(a->picture),
                                  GDK_PAINTABLE(tex));
        g_object_unref(tex);
        gtk_stack_set_visible_child_name(GTK_STACK(a->stack), "render");
      } else {
        show_message(a, err->message, TRUE);
        g_error_free(err);
      }
      show_message(a, a->diagnostics->str, FALSE);
    } else {
      show_message(a, a->diagnostics->str, TRUE);
    }
    gtk_progress_bar_set_fraction(GTK_PROGRESS_BAR(a->progress), 1.0);
  } else if (a->render_status == ZR_ECANCELLED) {
    show_message(a, "The render was cancelled.\n", FALSE);
    gtk_progress_bar_set_fraction(GTK_PROGRESS_BAR(a->progress), 0.0);
  } else {
    g_string_append_printf(a->diagnostics, "render: %s\n",
                           zr_status_str(a->render_status));
    show_message(a, a->diagnostics->str, TRUE);
  }
  zr_image_free(a->image);
  a->image = NULL;
  update_buttons(a);
  if (a->render_path != NULL) {
    /* --render: what Save would write, then quit. */
    GError *err = NULL;
    if (a->png == NULL) {
      fprintf(stderr, "zrcube-gtk: %s", a->diagnostics->str);
      a->exit_status = 1;
    } else if (!g_file_set_contents(a->render_path, (const char *)a->png,
                                    (gssize)a->png_size, &err)) {
      fprintf(stderr, "zrcube-gtk: %s\n", err->message);
      g_error_free(err);
      a->exit_status = 1;
    } else {
      a->exit_status = 0;
    }
    g_application_quit(G_APPLICATION(a->gtk));
  }
  return G_SOURCE_REMOVE;
}

static gpointer render_thread(gpointer data) {
  app *a = data;
  zr_render_params p;
  zr_render_params_init(&p);
  p.width = a->width;
  p.height = a->height;
  p.threads = (int)g_get_num_processors();
  p.context = a->ctx;
  a->render_status = zr_render_image(a->scene, &p,
                                     zr_image_pixels(a->image), NULL);
  g_idle_add(render_done, a);
  return NULL;
}

static void on_render_clicked(GtkButton *button, app *a) {
  (void)button;
  if (a->scene == NULL || a->worker != NULL)
    return;
  free(a->png);
  a->png = NULL;
  a->png_size = 0;
  zr_status st = zr_image_new(a->width, a->height, &a->image);
  if (st != ZR_OK) {
    show_message(a, zr_status_str(st), TRUE);
    return;
  }
  g_string_truncate(a->diagnostics, 0);
  atomic_store(&a->done, 0);
  atomic_store(&a->total, 0);
  gtk_progress_bar_set_fraction(GTK_PROGRESS_BAR(a->progress), 0.0);
  zr_context_set_progress(a->ctx, on_progress, a);
  show_message(a, "Rendering ...\n", FALSE);
  a->worker = g_thread_new("render", render_thread, a);
  update_buttons(a);
}

static void on_cancel_clicked(GtkButton *button, app *a) {
  (void)button;
  if (a->worker != NULL)
    zr_context_cancel(a->ctx, 1);
}

/* ---- files ---- */

static void on_open_response(GtkNativeDialog *dialog, int response,
                             app *a) {
  if (response == GTK_RESPONSE_ACCEPT) {
    GFile *f = gtk_file_chooser_get_file(GTK_FILE_CHOOSER(dialog));
    char *path = f ? g_file_get_path(f) : NULL;
    if (path != NULL && a->worker == NULL)
      load_scene(a, path);
    g_free(path);
    if (f)
      g_object_unref(f);
  }
  g_object_unref(dialog);
}

static void on_open_clicked(GtkButton *button, app *a) {
  (void)button;
  GtkFileChooserNative *d = gtk_file_chooser_native_new(
      "Open a scene", GTK_WINDOW(a->window), GTK_FILE_CHOOSER_ACTION_OPEN,
      "_Open", "_Cancel");
  GtkFileFilter *filter = gtk_file_filter_new();
  gtk_file_filter_set_name(filter, "POV-Ray scenes (*.pov)");
  gtk_file_filter_add_pattern(filter, "*.pov");
  gtk_file_chooser_add_filter(GTK_FILE_CHOOSER(d), filter);
  g_object_unref(filter);
  g_signal_connect(d, "response", G_CALLBACK(on_open_response), a);
  gtk_native_dialog_show(GTK_NATIVE_DIALOG(d));
}

static void on_save_response(GtkNativeDialog *dialog, int response,
                             app *a) {
  if (response == GTK_RESPONSE_ACCEPT && a->png != NULL) {
    GFile *f = gtk_file_chooser_get_file(GTK_FILE_CHOOSER(dialog));
    char *path = f ? g_file_get_path(f) : NULL;
    GError *err = NULL;
    if (path != NULL &&
        !g_file_set_contents(path, (const char *)a->png,
                             (gssize)a->png_size, &err)) {
      show_message(a, err->message, TRUE);
      g_error_free(err);
    }
    g_free(path);
    if (f)
      g_object_unref(f);
  }
  g_object_unref(dialog);
}

static void on_save_clicked(GtkButton *button, app *a) {
  (void)button;
  GtkFileChooserNative *d = gtk_file_chooser_native_new(
      "Save the picture", GTK_WINDOW(a->window),
      GTK_FILE_CHOOSER_ACTION_SAVE, "_Save", "_Cancel");
  gtk_file_chooser_set_current_name(GTK_FILE_CHOOSER(d), "render.png");
  g_signal_connect(d, "response", G_CALLBACK(on_save_response), a);
  gtk_native_dialog_show(GTK_NATIVE_DIALOG(d));
}

/* ---- input ---- */

static void on_drag_begin(GtkGestureDrag *g, double x, double y, app *a) {
  a->drag_yaw = a->yaw;
  a->drag_pitch = a->pitch;
}

static void on_drag_update(GtkGestureDrag *g, double dx, double dy, app *a) {
  /* Half a turn across 600 pixels. */
  a->yaw = a->drag_yaw + dx * M_PI / 600.0;
  a->pitch = a->drag_pitch + dy * M_PI / 600.0;
  if (a->pitch > 1.5)
    a->pitch = 1.5;
  if (a->pitch < -1.5)
    a->pitch = -1.5;
  gtk_gl_area_queue_render(GTK_GL_AREA(a->gl_area));
}

static gboolean on_scroll(GtkEventControllerScroll *c, double dx, double dy,
                          app *a) {
  a->zoom *= exp(0.1 * dy);
  if (a->zoom < 1e-3)
    a->zoom = 1e-3;
  if (a->zoom > 1e3)
    a->zoom = 1e3;
  gtk_gl_area_queue_render(GTK_GL_AREA(a->gl_area));
  return TRUE;
}

static gboolean on_key(GtkEventControllerKey *c, guint key, guint code,
                       GdkModifierType state, app *a) {
  if (key == GDK_KEY_r || key == GDK_KEY_R || key == GDK_KEY_Home) {
    reset_view(a);
    return TRUE;
  }
  return FALSE;
}

/* ---- window ---- */

static GtkWidget *button(const char *label, GCallback fn, app *a) {
  GtkWidget *b = gtk_button_new_with_mnemonic(label);
  g_signal_connect(b, "clicked", fn, a);
  return b;
}

static void on_activate(GtkApplication *gtk, app *a) {
  a->window = gtk_application_window_new(gtk);
  gtk_window_set_title(GTK_WINDOW(a->window), "zrcube-gtk");
  GtkWidget *header = gtk_header_bar_new();
  a->open_button = button("_Open", G_CALLBACK(on_open_clicked), a);
  a->render_button = button("_Render", G_CALLBACK(on_render_clicked), a);
  a->cancel_button = button("_Cancel", G_CALLBACK(on_cancel_clicked), a);
  a->save_button = button("_Save", G_CALLBACK(on_save_clicked), a);
  gtk_header_bar_pack_start(GTK_HEADER_BAR(header), a->open_button);
  gtk_header_bar_pack_start(GTK_HEADER_BAR(header), a->render_button);
  gtk_header_bar_pack_start(GTK_HEADER_BAR(header), a->cancel_button);
  gtk_header_bar_pack_end(GTK_HEADER_BAR(header), a->save_button);
  gtk_window_set_titlebar(GTK_WINDOW(a->window), header);

  GtkWidget *box = gtk_box_new(GTK_ORIENTATION_VERTICAL, 4);
  a->stack = gtk_stack_new();
  GtkWidget *switcher = gtk_stack_switcher_new();
  gtk_stack_switcher_set_stack(GTK_STACK_SWITCHER(switcher),
                               GTK_STACK(a->stack));
  gtk_header_bar_set_title_widget(GTK_HEADER_BAR(header), switcher);

  a->gl_area = gtk_gl_area_new();
  gtk_gl_area_set_required_version(GTK_GL_AREA(a->gl_area), 3, 2);
  gtk_gl_area_set_has_depth_buffer(GTK_GL_AREA(a->gl_area), TRUE);
  gtk_widget_set_size_request(a->gl_area, a->width, a->height);
  gtk_widget_set_hexpand(a->gl_area, TRUE);
  gtk_widget_set_vexpand(a->gl_area, TRUE);
  g_signal_connect(a->gl_area, "realize", G_CALLBACK(on_realize), a);
  g_signal_connect(a->gl_area, "unrealize", G_CALLBACK(on_unrealize), a);
  g_signal_connect(a->gl_area, "render", G_CALLBACK(on_render), a);
  GtkGesture *drag = gtk_gesture_drag_new();
  g_signal_connect(drag, "drag-begin", G_CALLBACK(on_drag_begin), a);
  g_signal_connect(drag, "drag-update", G_CALLBACK(on_drag_update), a);
  gtk_widget_add_controller(a->gl_area, GTK_EVENT_CONTROLLER(drag));
  GtkEventController *scroll =
      gtk_event_controller_scroll_new(GTK_EVENT_CONTROLLER_SCROLL_VERTICAL);
  g_signal_connect(scroll, "scroll", G_CALLBACK(on_scroll), a);
  gtk_widget_add_controller(a->gl_area, scroll);
  GtkEventController *keys = gtk_event_controller_key_new();
  g_signal_connect(keys, "key-pressed", G_CALLBACK(on_key), a);
  gtk_widget_add_controller(a->window, keys);
  gtk_stack_add_titled(GTK_STACK(a->stack), a->gl_area, "preview",
                       "Preview");

  a->picture = gtk_picture_new();
  gtk_picture_set_can_shrink(GTK_PICTURE(a->picture), TRUE);
  gtk_stack_add_titled(GTK_STACK(a->stack), a->picture, "render", "Render");
  gtk_box_append(GTK_BOX(box), a->stack);

  a->progress = gtk_progress_bar_new();
  gtk_box_append(GTK_BOX(box), a->progress);
  a->status = gtk_label_new("no scene");
  gtk_label_set_xalign(GTK_LABEL(a->status), 0.0f);
  gtk_label_set_wrap(GTK_LABEL(a->status), TRUE);
  gtk_box_append(GTK_BOX(box), a->status);
  a->message = gtk_label_new("");
  gtk_label_set_xalign(GTK_LABEL(a->message), 0.0f);
  gtk_label_set_selectable(GTK_LABEL(a->message), TRUE);
  gtk_label_set_wrap(GTK_LABEL(a->message), TRUE);
  gtk_widget_add_css_class(a->message, "monospace");
  GtkWidget *scroller = gtk_scrolled_window_new();
  gtk_scrolled_window_set_child(GTK_SCROLLED_WINDOW(scroller), a->message);
  gtk_scrolled_window_set_min_content_height(GTK_SCROLLED_WINDOW(scroller),
                                             80);
  gtk_box_append(GTK_BOX(box), scroller);
  gtk_window_set_child(GTK_WINDOW(a->window), box);

  update_buttons(a);
  if (a->scene_path != NULL)
    load_scene(a, a->scene_path);
  if (a->screenshot_path != NULL)
    g_timeout_add_seconds(60, screenshot_timeout, a);

  gtk_window_present(GTK_WINDOW(a->window));
}

static void on_shutdown(GApplication *gapp, app *a) {
  if (a->worker != NULL) {
    zr_context_cancel(a->ctx, 1);
    g_thread_join(a->worker);
    a->worker = NULL;
  }
}

static void usage(FILE *to) {
  fprintf(to,
          "Usage: zrcube-gtk [--width N] [--height N] "
          "[--orbit YAW,PITCH,ZOOM]\n"
          "                  [--screenshot FILE | --render FILE] "
          "[SCENE.pov]\n"
          "Previews a POV-Ray scene with OpenGL from its camera, renders it "
          "with libzrcube\nand saves the picture.  --screenshot draws the "
          "preview once into FILE (PNG)\nand exits; --render renders as the "
          "Render button does, saves as Save does,\nand exits.  See "
          "zrcube-gtk(1).\n");
}

static bool parse_size(const char *s, int *out) {
  char *end;
  long v = strtol(s, &end, 10);
  if (*s == '\0' || *end != '\0' || v < 1 || v > 16384)
    return false;
  *out = (int)v;
  return true;
}

int main(int argc, char **argv) {
  app a;
  memset(&a, 0, sizeof a);
  a.width = DEFAULT_WIDTH;
  a.height = DEFAULT_HEIGHT;
  a.zoom = 1.0;
  for (int i = 1; i < argc; i++) {
    const char *arg = argv[i];
    if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
      usage(stdout);
      return 0;
    }
    if (strcmp(arg, "--version") == 0) {
      printf("zrcube-gtk (libzrcube %s)\n", zr_version());
      return 0;
    }
    if (strcmp(arg, "--orbit") == 0) {
      char *end = NULL;
      const char *val = i + 1 < argc ? argv[++i] : "";
      int k = 0;
      for (const char *q = val; k < 3; k++, q = end + 1) {
        a.orbit[k] = strtod(q, &end);
        if (end == q || !isfinite(a.orbit[k]) || (k < 2 && *end != ',') ||
            (k == 2 && *end != '\0'))
          break;
      }
      if (k < 3 || !(a.orbit[2] >= 1e-3 && a.orbit[2] <= 1e3)) {
        fprintf(stderr, "zrcube-gtk: --orbit takes YAW,PITCH,ZOOM (degrees, "
                        "degrees, a factor from 0.001 to 1000), not \"%s\"\n",
                val);
        return 2;
      }
      a.have_orbit = true;
      continue;
    }
    if (strcmp(arg, "--width") == 0 || strcmp(arg, "--height") == 0 ||
        strcmp(arg, "--screenshot") == 0 || strcmp(arg, "--render") == 0) {
      if (i + 1 >= argc) {
        fprintf(stderr, "zrcube-gtk: %s needs a value\n", arg);
        return 2;
      }
      const char *val = argv[++i];
      if (strcmp(arg, "--screenshot") == 0) {
        g_free(a.screenshot_path);
        a.screenshot_path = g_strdup(val);
      } else if (strcmp(arg, "--render") == 0) {
        g_free(a.render_path);
        a.render_path = g_strdup(val);
      } else if (!parse_size(val, strcmp(arg, "--width") == 0 ? &a.width
                                                              : &a.height)) {
        fprintf(stderr, "zrcube-gtk: %s takes a whole number from 1 to "
                        "16384, not \"%s\"\n", arg, val);
        return 2;
      }
    } else if (arg[0] == '-' && arg[1] != '\0') {
      fprintf(stderr, "zrcube-gtk: unknown option \"%s\"\n", arg);
      usage(stderr);
      return 2;
    } else if (a.scene_path != NULL) {
      fprintf(stderr, "zrcube-gtk: one scene at a time (\"%s\" and \"%s\")\n",
              a.scene_path, arg);
      return 2;
    } else {
      a.scene_path = g_strdup(arg);
    }
  }
  if ((a.screenshot_path != NULL || a.render_path != NULL) &&
      a.scene_path == NULL) {
    fprintf(stderr, "zrcube-gtk: --screenshot and --render need a scene\n");
    return 2;
  }
  if (a.screenshot_path != NULL && a.render_path != NULL) {
    fprintf(stderr, "zrcube-gtk: --screenshot or --render, not both\n");
    return 2;
  }
  a.exit_status = a.screenshot_path != NULL || a.render_path != NULL;
  a.diagnostics = g_string_new(NULL);
  a.gtk = gtk_application_new(NULL, G_APPLICATION_NON_UNIQUE);
  g_signal_connect(a.gtk, "activate", G_CALLBACK(on_activate), &a);
  g_signal_connect(a.gtk, "shutdown", G_CALLBACK(on_shutdown), &a);
  char *gapp_argv[] = {argv[0], NULL};
  int status = g_application_run(G_APPLICATION(a.gtk), 1, gapp_argv);
  g_object_unref(a.gtk);
  zr_preview_free(a.preview);
  zr_scene_free(a.scene);
  zr_preview_free(a.loaded_preview);
  zr_scene_free(a.loaded_scene);
  zr_context_free(a.ctx);
  zr_image_free(a.image);
  free(a.png);
  g_free(a.scene_path);
  g_free(a.screenshot_path);
  g_free(a.render_path);
  g_free(a.load_path);
  g_string_free(a.diagnostics, TRUE);
  return status != 0 ? status : a.exit_status;
}
