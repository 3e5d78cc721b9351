/* The attitude animation: the exact motion, the midpoint rule and the variational integrator
 * side by side, at eps = 1 with R_{k+1} = R_k cay(eps w^_k) (Algorithm (algo)), rendered off
 * screen with OSMesa; labels and time drawn with Cairo onto each frame.
 * Usage: animation [--quiet] CONFIG FIGDIR DATADIR (--quiet: no progress line)
 * Writes FIGDIR/attitude/frame_NNNN.png, FIGDIR/attitude.mp4 (when ffmpeg is installed and
 * SUSLOV_NO_VIDEO is unset), FIGDIR/attitude_filmstrip.png, FIGDIR/attitude.txt, and
 * DATADIR/attitude.csv: the R_k of both integrators at every step, exactly as `suslov` prints
 * them for the same settings (the same driver).
 * On every exit path - an error, or SIGINT/SIGTERM/SIGHUP - the ffmpeg child is stopped and
 * waited for, and the temporary video and frame files are removed (animation_video.c). */
#define _POSIX_C_SOURCE 200809L
#include "animation_video.h"
#include "atomic_file.h"
#include "plot.h"
#include "driver.h"
#include "exact.h"
#include "fig_output.h"
#include "frame_png.h"
#include "gl_context.h"
#include "mat3.h"
#include "progress.h"
#include "refattitude.h"
#include "scene.h"
#include "so3.h"
#include "dsp.h"

#include <GL/gl.h>
#include <cairo.h>
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* What main allocates, released at exit on every path (an error return included). */
static struct {
    sus_row *rows[2];
    sus_plot_gl_context *gl;
    uint32_t *strip;
} owned;

static void release_owned(void)
{
    for (int m = 0; m < 2; m++)
        free(owned.rows[m]);
    if (owned.gl)
        sus_plot_gl_context_destroy(owned.gl);
    free(owned.strip);
    memset(&owned, 0, sizeof owned);
}

typedef struct {
    int width, height, fps;
    double seconds, t_end, eps;
} anim_config;

static int read_config(const char *path, anim_config *c)
{
    *c = (anim_config){1280, 720, 30, 10.0, 60.0, 1.0};
    FILE *fp = fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "animation: %s: %s; using the defaults\n", path, strerror(errno));
        return 0;
    }
    char line[256];
    int lineno = 0;
    while (fgets(line, sizeof line, fp)) {
        char key[64];
        double v;
        lineno++;
        if (line[0] == '#' || line[strspn(line, " \t\r\n")] == '\0')
            continue;
        if (sscanf(line, " %63[a-z_] = %lf", key, &v) != 2 || !isfinite(v)) {
            fprintf(stderr, "animation: %s:%d: expected 'key = number'\n", path, lineno);
            fclose(fp);
            return -1;
        }
        if (strcmp(key, "width") == 0)
            c->width = (int)v;
        else if (strcmp(key, "height") == 0)
            c->height = (int)v;
        else if (strcmp(key, "fps") == 0)
            c->fps = (int)v;
        else if (strcmp(key, "seconds") == 0)
            c->seconds = v;
        else if (strcmp(key, "t_end") == 0)
            c->t_end = v;
        else if (strcmp(key, "eps") == 0)
            c->eps = v;
        else {
            fprintf(stderr, "animation: %s:%d: unknown key '%s'\n", path, lineno, key);
            fclose(fp);
            return -1;
        }
    }
    fclose(fp);
    if (c->width < 48 || c->width > 4096 || c->height < 27 || c->height > 4096 || c->width % 2 ||
        c->height % 2 || c->fps < 1 || c->fps > 120 || !(c->seconds > 0) || !(c->t_end > 0) ||
        !(c->eps > 0)) {
        fprintf(stderr,
                "animation: %s: out of range (even width/height "
                "48..4096, fps 1..120, positive times)\n",
                path);
        return -1;
    }
    return 0;
}

/* ---- the three motions ---- */

typedef struct {
    long n; /* rows 0..n */
    sus_row *rows;
} dsp_track;

static int store(void *vctx, const sus_row *row)
{
    dsp_track *t = vctx;
    if (row->k > t->n)
        return 1;
    t->rows[row->k] = *row;
    return 0;
}

/* The attitude between steps follows the retraction curve of the step: R_k cay(s w^_k),
 * s in [0, eps): at the step times it is R_k itself. */
static void dsp_state(const dsp_track *t, double eps, double time, double R[3][3], double w[3])
{
    long k = (long)floor(time / eps + 1e-9);
    if (k > t->n)
        k = t->n;
    const sus_row *r = &t->rows[k];
    const double s = time - (double)k * eps;
    double xi[3] = {s * r->w[0], s * r->w[1], s * r->w[2]}, C[3][3];
    sus_so3_cay(xi, C);
    sus_mat3_mul(R, r->R, C);
    memcpy(w, r->w, 3 * sizeof(double));
}

static int write_attitude_csv(const char *path, const dsp_track *t, const char *const *names,
                              int nm)
{
    char err[256];
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "animation: %s\n", err);
        return -1;
    }
    fprintf(af.fp, "method,k,t,R11,R12,R13,R21,R22,R23,R31,R32,R33\n");
    for (int m = 0; m < nm; m++)
        for (long k = 0; k <= t[m].n; k++) {
            const sus_row *r = &t[m].rows[k];
            fprintf(af.fp, "%s,%ld,%.17g", names[m], r->k, r->t);
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    fprintf(af.fp, ",%.17g", r->R[i][j]);
            fputc('\n', af.fp);
        }
    if (sus_sys_atomic_file_commit(&af, err, sizeof err) != 0) {
        fprintf(stderr, "animation: %s\n", err);
        return -1;
    }
    return 0;
}

/* ---- frames ---- */

static const char *const LABELS[3] = {"exact", "midpoint, \xce\xb5 = 1",
                                      "variational, \xce\xb5 = 1"};

/* The key to what each body carries, in two columns of up to three rows along the bottom from x0:
 * a swatch of the scene's own colour (a stroke for an arrow, a square for the box), and what it
 * is. */
static void draw_key(cairo_t *cr, double x0, int H, double fs)
{
    static const struct {
        const double *rgb;
        int square, col, row;
        const char *text;
    } KEY[] = {
        {SUS_PLOT_SCENE_RGB_E3, 0, 0, 0,
         "e\xe2\x82\x83, along which \xcf\x89 must vanish, and the trail of its tip"},
        {SUS_PLOT_SCENE_RGB_AXES, 0, 0, 1, "e\xe2\x82\x81, e\xe2\x82\x82: the other body axes"},
        {SUS_PLOT_SCENE_RGB_STAND, 0, 0, 2, "the stand, with the fixed point at its top"},
        {SUS_PLOT_SCENE_RGB_OMEGA, 0, 1, 0, "\xcf\x89, the angular velocity, drawn in space"},
        {SUS_PLOT_SCENE_RGB_BOX, 1, 1, 1, "the body: the principal axes of I's symmetric part"},
    };
    enum { N = sizeof KEY / sizeof KEY[0] };
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, fs);
    cairo_set_line_width(cr, 0.3 * fs);
    double col1 = 0.0; /* the second column starts past the first's widest text */
    for (int i = 0; i < N; i++) {
        cairo_text_extents_t te;
        cairo_text_extents(cr, KEY[i].text, &te);
        if (KEY[i].col == 0 && te.x_advance > col1)
            col1 = te.x_advance;
    }
    for (int i = 0; i < N; i++) {
        const double x = x0 + (KEY[i].col ? col1 + 2.5 * fs : 0.0),
                     y = H - (2.6 - KEY[i].row) * 1.5 * fs;
        cairo_set_source_rgb(cr, KEY[i].rgb[0], KEY[i].rgb[1], KEY[i].rgb[2]);
        if (KEY[i].square) {
            cairo_rectangle(cr, x + 0.3 * fs, y - 0.8 * fs, 0.8 * fs, 0.8 * fs);
            cairo_fill(cr);
        } else {
            cairo_move_to(cr, x, y - 0.35 * fs);
            cairo_line_to(cr, x + 1.4 * fs, y - 0.35 * fs);
            cairo_stroke(cr);
        }
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, x + 1.8 * fs, y);
        cairo_show_text(cr, KEY[i].text);
    }
}

static void label_frame(uint32_t *px, int W, int H, double time, int with_key)
{
    cairo_surface_t *s =
        cairo_image_surface_create_for_data((unsigned char *)px, CAIRO_FORMAT_ARGB32, W, H, 4 * W);
    cairo_t *cr = cairo_create(s);
    const double fs = H / 18.0;
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, fs);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    for (int b = 0; b < 3; b++) {
        cairo_text_extents_t te;
        cairo_text_extents(cr, LABELS[b], &te);
        cairo_move_to(cr, (b + 0.5) * W / 3.0 - 0.5 * te.x_advance, 1.3 * fs);
        cairo_show_text(cr, LABELS[b]);
    }
    char buf[32];
    snprintf(buf, sizeof buf, "t = %5.2f", time);
    cairo_set_font_size(cr, 0.9 * fs);
    cairo_move_to(cr, 0.6 * fs, H - 0.6 * fs);
    cairo_show_text(cr, buf);
    if (with_key)
        draw_key(cr, 6.0 * fs, H, 0.45 * fs);
    cairo_destroy(cr);
    cairo_surface_flush(s);
    cairo_surface_destroy(s);
}

/* Writes the surface to path through the atomic file (plot.h): complete or not at all. */
static int write_surface_png(cairo_surface_t *s, const char *path)
{
    char err[512];
    if (sus_plot_write_surface_png(s, path, err, sizeof err) != 0) {
        fprintf(stderr, "animation: %s\n", err);
        return -1;
    }
    return 0;
}

/* A frame through frame_png.h's fast writer: frames are many and never committed. */
static int write_png(const uint32_t *px, int W, int H, const char *path)
{
    char err[512];
    if (sus_plot_write_frame_png(px, W, H, path, err, sizeof err) != 0) {
        fprintf(stderr, "animation: %s\n", err);
        return -1;
    }
    return 0;
}

/* Times of the filmstrip frames, as fractions of t_end. */
static const double STRIP[6] = {0.0, 1.0 / 12, 1.0 / 6, 1.0 / 3, 2.0 / 3, 1.0};

/* At exit, the owned memory is released after the video's clean-up (atexit runs in reverse). */
static void handle_signals(void)
{
    atexit(release_owned);
    suslov_video_guard();
}

static const char *const NAMES[2] = {"midpoint", "variational"};

/* The two integrators through the driver, every step kept (N is small). */
static int run_integrators(const anim_config *cfg, const sus_model *model, const sus_exact *ex,
                           dsp_track track[2])
{
    const long N = (long)ceil(cfg->t_end / cfg->eps - 1e-9);
    const sus_stepper_type *st[2] = {sus_step_midpoint, sus_step_variational};
    for (int m = 0; m < 2; m++) {
        track[m].n = N;
        track[m].rows = owned.rows[m] = calloc((size_t)N + 1, sizeof(sus_row));
        const sus_run_config rc = {model, st[m], SUS_RECON_CAYLEY, cfg->eps, N, 1};
        sus_run_report rep;
        if (!track[m].rows || sus_run(&rc, ex->w0, store, &track[m], &rep) != 0) {
            fprintf(stderr, "animation: %s failed at step %ld (t = %g)\n", NAMES[m], rep.step,
                    rep.t);
            return -1;
        }
    }
    return 0;
}

/* What the frame loop draws from and into. */
typedef struct {
    const anim_config *cfg;
    const sus_exact *ex;
    const dsp_track *track;
    sus_plot_scene sc;
    uint32_t *px, *strip;
    int W, H, nframes, strip_next;
    sus_plot_scene_body body[3];
} frames;

/* Frame f: the exact body and the two integrators side by side, labelled, to PNG and video. */
static int draw_frame(frames *fr, sus_refatt *ra, int f, const char *figdir, FILE **video)
{
    const anim_config *cfg = fr->cfg;
    const int W = fr->W, H = fr->H;
    const double time = cfg->t_end * f / (fr->nframes > 1 ? fr->nframes - 1 : 1);
    double wex[2];
    char path[4096];
    sus_exact_omega(fr->ex, time, wex);
    fr->body[0].w[0] = wex[0];
    fr->body[0].w[1] = wex[1];
    sus_refatt_advance(ra, time, fr->body[0].R);
    for (int m = 0; m < 2; m++)
        dsp_state(&fr->track[m], cfg->eps, time, fr->body[1 + m].R, fr->body[1 + m].w);
    glClearColor(0.97f, 0.97f, 0.95f, 1.0f);
    glViewport(0, 0, W, H);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (int b = 0; b < 3; b++) {
        sus_plot_scene_body_push_trail(&fr->body[b]);
        sus_plot_scene_draw(&fr->sc, &fr->body[b], b * (W / 3), 0, W / 3, H, 0);
    }
    glFinish();
    /* the filmstrip's frames without the key: the strip prints one key, large enough to read */
    while (fr->strip && fr->strip_next < 6 && time >= STRIP[fr->strip_next] * cfg->t_end - 1e-9) {
        uint32_t *dst = fr->strip + (size_t)(fr->strip_next++) * W * H;
        memcpy(dst, fr->px, (size_t)W * H * sizeof(uint32_t));
        label_frame(dst, W, H, time, 0);
    }
    label_frame(fr->px, W, H, time, 1);
    snprintf(path, sizeof path, "%s/attitude/frame_%04d.png", figdir, f);
    if (write_png(fr->px, W, H, path) != 0)
        return -1;
    suslov_video_frame(video, fr->px, W, H);
    return 0;
}

/* The filmstrip: 2 columns x 3 rows of frames at the STRIP times, and below them one key for all
 * six, its text as tall as the frames' time labels (which the software note prints at 7 pt). No
 * title: the caption that prints it (attitude.txt, the software note) says what it shows. */
static int write_filmstrip(const frames *fr, const char *figdir)
{
    const int W = fr->W, H = fr->H, SW = 2 * W;
    const double fs = 0.9 * H / 18.0; /* label_frame's time label */
    const int SH = 3 * H + (int)ceil(5.5 * fs);
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, SW, SH);
    cairo_t *cr = cairo_create(s);
    cairo_set_source_rgb(cr, 0.97, 0.97, 0.95); /* the frames' background */
    cairo_paint(cr);
    draw_key(cr, 0.6 * fs, SH, fs);
    for (int i = 0; i < 6; i++) {
        cairo_surface_t *f = cairo_image_surface_create_for_data(
            (unsigned char *)(fr->strip + (size_t)i * W * H), CAIRO_FORMAT_ARGB32, W, H, 4 * W);
        cairo_set_source_surface(cr, f, (i % 2) * W, (i / 2) * H);
        cairo_paint(cr);
        cairo_surface_destroy(f);
    }
    cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
    cairo_set_line_width(cr, 2.0);
    cairo_move_to(cr, W, 0);
    cairo_line_to(cr, W, 3 * H);
    for (int r = 1; r <= 3; r++) {
        cairo_move_to(cr, 0, r * H);
        cairo_line_to(cr, SW, r * H);
    }
    cairo_stroke(cr);
    cairo_destroy(cr);
    char path[4096];
    snprintf(path, sizeof path, "%s/attitude_filmstrip.png", figdir);
    const int bad = write_surface_png(s, path);
    cairo_surface_destroy(s);
    return bad;
}

static int write_caption(const anim_config *cfg, const frames *fr, const char *figdir)
{
    const int W = fr->W, H = fr->H, nframes = fr->nframes;
    const sus_plot_scene_body *body = fr->body;
    char path[4096];
    double dist[2];
    for (int m = 0; m < 2; m++)
        dist[m] = sus_so3_dist(body[0].R, body[1 + m].R);
    char cap[2048];
    snprintf(cap, sizeof cap,
             "Attitude animation. Regenerate: make animation (or "
             "make figures); settings in data/animation.cfg.\n"
             "Three copies of the body: the exact motion (R from the reference "
             "attitude along the closed-form w), the midpoint rule\n"
             "and the variational integrator, both at eps = %g "
             "with R_{k+1} = R_k cay(eps w^_k) ((algo)),\n"
             "inertia as printed, w(0) = (0.4, 0.5), t in [0, %g]. "
             "Between steps the attitude follows the step's own\n"
             "retraction curve R_k cay(s w^_k), s in [0, eps); at step "
             "times it is R_k exactly, as `suslov` prints it\n"
             "(data/attitude.csv). The box has the principal axes "
             "and relative extents of the symmetric part of I;\n"
             "grey arrows e1, e2, red arrow e3 (the direction along "
             "which w must vanish) with its fading trail,\n"
             "orange arrow: w in space, R w. The distance of (MetMat) "
             "to the exact attitude at t = %g: midpoint %.3f,\n"
             "variational %.3f. %d frames of %dx%d at %d fps: figures/attitude/frame_NNNN.png, "
             "figures/attitude.mp4.\n"
             "Filmstrip rows: t = %.3g, %.3g / %.3g, %.3g / %.3g, %.3g.\n",
             cfg->eps, cfg->t_end, cfg->t_end, dist[0], dist[1], nframes, W, H, cfg->fps,
             STRIP[0] * cfg->t_end, STRIP[1] * cfg->t_end, STRIP[2] * cfg->t_end,
             STRIP[3] * cfg->t_end, STRIP[4] * cfg->t_end, STRIP[5] * cfg->t_end);
    if (sus_plot_fig_write_text(sus_plot_fig_path(path, sizeof path, figdir, "attitude", "txt"),
                                cap) != 0)
        return -1;
    return 0;
}

/* Renders every frame, the video and the filmstrip, with the progress (modes: progress.h). */
static int render(frames *fr, const anim_config *cfg, const char *figdir, int modes)
{
    char path[4096], mp4[4096];
    snprintf(path, sizeof path, "%s/attitude", figdir);
    if (mkdir(path, 0755) != 0 && errno != EEXIST) {
        fprintf(stderr, "animation: cannot create %s: %s\n", path, strerror(errno));
        return -1;
    }
    snprintf(mp4, sizeof mp4, "%s/attitude.mp4", figdir);
    FILE *video = suslov_video_open(cfg->width, cfg->height, cfg->fps, figdir, mp4);
    sus_refatt ra;
    double I3[3][3];
    sus_mat3_identity(I3);
    sus_refatt_init(&ra, fr->ex, 0.0, I3);
    fr->strip = owned.strip = malloc(6 * (size_t)fr->W * fr->H * sizeof(uint32_t));
    suslov_progress_start("animation", "frame", fr->nframes, modes);
    for (int f = 0; f < fr->nframes; f++) {
        suslov_progress_tick(f, NULL);
        if (draw_frame(fr, &ra, f, figdir, &video) != 0)
            return -1;
    }
    suslov_progress_end();
    suslov_video_close(video, mp4);
    if (fr->strip && fr->strip_next == 6 && write_filmstrip(fr, figdir) != 0)
        return -1;
    free(fr->strip);
    owned.strip = fr->strip = NULL;
    return 0;
}

int main(int argc, char **argv)
{
    const int modes = suslov_progress_modes(&argc, argv);
    if (argc != 4) {
        fprintf(stderr, "usage: animation [--quiet] CONFIG FIGDIR DATADIR\n");
        return 2;
    }
    gsl_set_error_handler_off();
    anim_config cfg;
    if (read_config(argv[1], &cfg) != 0)
        return 2;
    const char *figdir = argv[2], *datadir = argv[3];
    char err[256], path[4096];
    sus_model model;
    sus_exact ex;
    if (sus_model_init(&model, SUS_PAPER_INERTIA, err, sizeof err) != 0) {
        fprintf(stderr, "animation: the paper's inertia is rejected: %s\n", err);
        return 1;
    }
    sus_exact_init(&ex, &model, SUS_PAPER_OMEGA0);
    handle_signals();
    dsp_track track[2];
    if (run_integrators(&cfg, &model, &ex, track) != 0)
        return 3;
    if (write_attitude_csv(sus_plot_fig_path(path, sizeof path, datadir, "attitude", "csv"), track,
                           NAMES, 2) != 0)
        return 1;
    frames fr = {.cfg = &cfg,
                 .ex = &ex,
                 .track = track,
                 .W = cfg.width,
                 .H = cfg.height,
                 .nframes = (int)lround(cfg.fps * cfg.seconds)};
    sus_plot_gl_context *gl = owned.gl = sus_plot_gl_context_create(fr.W, fr.H);
    if (!gl || sus_plot_scene_init(&fr.sc, &model, fr.W / 3, fr.H) != 0) {
        fprintf(stderr, "animation: cannot create an off-screen OpenGL context (OSMesa)\n");
        return 1;
    }
    fr.px = sus_plot_gl_context_pixels(gl);
    if (render(&fr, &cfg, figdir, modes) != 0 || write_caption(&cfg, &fr, figdir) != 0)
        return 1;
    return 0; /* the rows and the GL context are released at exit (release_owned) */
}
