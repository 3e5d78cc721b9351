#define _POSIX_C_SOURCE 200809L
#include "plot.h"

#include "atomic_file.h"

#include <cairo-pdf.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define PLOT_PI 3.14159265358979323846

const double SUS_PLOT_PALETTE[SUS_PLOT_PALETTE_N][3] = {
    {0.90, 0.62, 0.00}, {0.00, 0.62, 0.45}, {0.80, 0.47, 0.65}, {0.00, 0.45, 0.70},
    {0.84, 0.37, 0.00}, {0.34, 0.71, 0.91}, {0.60, 0.10, 0.15}, {0.20, 0.20, 0.20},
    {0.55, 0.35, 0.10}, {0.40, 0.40, 0.85}, {0.10, 0.40, 0.20}, {0.65, 0.65, 0.00}};
const double SUS_PLOT_RED[3] = {0.85, 0.15, 0.10}, SUS_PLOT_BLUE[3] = {0.12, 0.35, 0.80},
             SUS_PLOT_GREEN[3] = {0.10, 0.60, 0.20}, SUS_PLOT_ORANGE[3] = {0.95, 0.55, 0.05},
             SUS_PLOT_PURPLE[3] = {0.55, 0.25, 0.70}, SUS_PLOT_GREY[3] = {0.45, 0.45, 0.45},
             SUS_PLOT_BLACK[3] = {0.0, 0.0, 0.0};

#define TICK_FONT SUS_PLOT_MIN_FONT
#define LABEL_FONT 10.0
#define LEGEND_ROW 11.0 /* a legend line, and the padding of its box */
#define LEGEND_PAD 4.0
#define LEGEND_SAMPLE 18.0
#define LEGEND_FONT SUS_PLOT_MIN_FONT

sus_plot_style sus_plot_style_of(const double rgb[3], double width, int dash, int marker, double size,
                         const char *label)
{
    return (sus_plot_style){rgb[0], rgb[1], rgb[2], width, dash, marker, size, label};
}

void sus_plot_extend(double *lo, double *hi, const double *v, size_t n, size_t stride, int log)
{
    for (size_t i = 0; i < n; i += stride) {
        if (!isfinite(v[i]) || (log && !(v[i] > 0.0)))
            continue;
        *lo = fmin(*lo, v[i]);
        *hi = fmax(*hi, v[i]);
    }
}

void sus_plot_pad(double *lo, double *hi, int log)
{
    if (!(*lo <= *hi)) { /* nothing to show */
        *lo = log ? 0.1 : 0.0;
        *hi = log ? 10.0 : 1.0;
    }
    if (log) {
        *lo = pow(10.0, floor(log10(*lo) + 1e-9));
        *hi = pow(10.0, ceil(log10(*hi) - 1e-9));
        if (*hi <= *lo)
            *hi = *lo * 10.0;
        return;
    }
    double span = *hi - *lo;
    if (span <= 1e-300 || span < 1e-12 * fmax(fabs(*lo), fabs(*hi))) {
        const double c = 0.5 * (*lo + *hi), d = fmax(fabs(c) * 1e-3, 1e-300);
        *lo = c - d;
        *hi = c + d;
        span = *hi - *lo;
    }
    *lo -= 0.05 * span;
    *hi += 0.05 * span;
}

void sus_plot_axes_init(sus_plot_axes *ax, cairo_t *cr, double x, double y, double w, double h,
                    double x0, double x1, double y0, double y1, int xlog, int ylog)
{
    *ax = (sus_plot_axes){cr, x, y, w, h, x0, x1, y0, y1, xlog, ylog, 0};
}

void sus_plot_cell(double width, double height, int rows, int cols, int idx, double *x, double *y,
               double *w, double *h)
{
    const double left = 64.0, right = 14.0, top = 40.0, bottom = 36.0, hgap = 70.0, vgap = 50.0;
    *w = (width - left - right - (cols - 1) * hgap) / cols;
    *h = (height - top - bottom - (rows - 1) * vgap) / rows;
    *x = left + (idx % cols) * (*w + hgap);
    *y = top + (idx / cols) * (*h + vgap);
}

void sus_plot_axes_cell(sus_plot_axes *ax, cairo_t *cr, double width, double height, int rows, int cols,
                    int idx, double x0, double x1, double y0, double y1, int xlog, int ylog)
{
    double x, y, w, h;
    sus_plot_cell(width, height, rows, cols, idx, &x, &y, &w, &h);
    sus_plot_pad(&y0, &y1, ylog);
    if (xlog) { /* a whole decade of padding would leave the data in a corner */
        x0 /= 1.25;
        x1 *= 1.25;
    }
    sus_plot_axes_init(ax, cr, x, y, w, h, x0, x1, y0, y1, xlog, ylog);
}

static double tx(double v, int log) { return log ? log10(v) : v; }

static double map_x(const sus_plot_axes *ax, double v)
{
    return ax->x +
           (tx(v, ax->xlog) - tx(ax->x0, ax->xlog)) / (tx(ax->x1, ax->xlog) - tx(ax->x0, ax->xlog)) * ax->w;
}

static double map_y(const sus_plot_axes *ax, double v)
{
    return ax->y + ax->h -
           (tx(v, ax->ylog) - tx(ax->y0, ax->ylog)) / (tx(ax->y1, ax->ylog) - tx(ax->y0, ax->ylog)) * ax->h;
}

/* A Unicode subscript or superscript of the labels (UTF-8 at s): the ASCII character it stands for
 * and its shift (-1 below, +1 above the baseline); returns its length in bytes, 0 if s is none.
 * The fonts draw these glyphs at about 0.6 of the size, too small at print size, so the plots set
 * them as ordinary characters at SCRIPT_SCALE of the size, moved off the baseline. */
#define SCRIPT_SCALE 0.8
static int script_of(const char *s, char *ascii, int *shift)
{
    static const struct { const char *utf8; char ascii; int shift; } other[] = {
        {"\xe2\x82\x8a", '+', -1}, {"\xe2\x82\x8b", '-', -1}, {"\xe2\x82\x96", 'k', -1},
        {"\xe2\x82\x98", 'm', -1}, {"\xe2\x82\x99", 'n', -1},
        {"\xe1\xb5\x80", 'T', 1},  {"\xe1\xb5\x96", 'p', 1}};
    const unsigned char *u = (const unsigned char *)s;
    if (u[0] == 0xe2 && u[1] == 0x82 && u[2] >= 0x80 && u[2] <= 0x89) { /* subscript digits */
        *ascii = (char)('0' + (u[2] - 0x80));
        *shift = -1;
        return 3;
    }
    for (size_t i = 0; i < sizeof other / sizeof other[0]; i++)
        if (strncmp(s, other[i].utf8, 3) == 0) {
            *ascii = other[i].ascii;
            *shift = other[i].shift;
            return 3;
        }
    return 0;
}

/* Sets one piece of text at (x, y) (baseline) when draw is set; returns its advance. No piece is
 * set below the smallest size that stays legible in print. */
static double piece(cairo_t *cr, double x, double y, const char *text, double size, int draw)
{
    cairo_text_extents_t te;
    cairo_set_font_size(cr, fmax(size, SUS_PLOT_MIN_FONT));
    cairo_text_extents(cr, text, &te);
    if (draw) {
        cairo_move_to(cr, x, y);
        cairo_show_text(cr, text);
    }
    return te.x_advance;
}

/* The advance of a label, its scripts set as script_of says; drawn from (x, y) when draw is set. */
static double label_runs(cairo_t *cr, double x, double y, const char *text, double size, int draw)
{
    char run[256], one[2] = {0, 0};
    size_t n = 0;
    double adv = 0.0;
    for (const char *s = text;;) {
        int shift = 0, len = *s ? script_of(s, one, &shift) : 0;
        if (!*s || len || n + 1 == sizeof run) {
            run[n] = '\0';
            adv += n ? piece(cr, x + adv, y, run, size, draw) : 0.0;
            n = 0;
        }
        if (!*s)
            return adv;
        if (len) {
            const double dy = shift < 0 ? 0.22 * size : -0.38 * size;
            adv += piece(cr, x + adv, y + dy, one, SCRIPT_SCALE * size, draw);
            s += len;
        } else
            run[n++] = *s++;
    }
}

void sus_plot_text(cairo_t *cr, double x, double y, const char *text, double size, double halign,
               double valign, int bold)
{
    cairo_select_font_face(cr, SUS_PLOT_FONT, CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    const double w = label_runs(cr, 0.0, 0.0, text, size, 0);
    /* valign: 0 = top, 0.5 = middle, 1 = baseline-ish bottom of the cap height */
    label_runs(cr, x - halign * w, y + (1.0 - valign) * size * 0.72, text, size, 1);
}

/* Width of a text at a size, for layout. */
static double text_width(cairo_t *cr, const char *text, double size)
{
    cairo_select_font_face(cr, SUS_PLOT_FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    return label_runs(cr, 0.0, 0.0, text, size, 0);
}

/* "10" with a raised exponent, aligned like sus_plot_text. The exponent keeps the tick size, the
 * smallest that stays legible in print (SUS_PLOT_MIN_FONT). */
static void power_label(cairo_t *cr, double x, double y, int e, double halign, double valign)
{
    char ex[16];
    snprintf(ex, sizeof ex, "%d", e);
    const double w10 = text_width(cr, "10", TICK_FONT), we = text_width(cr, ex, TICK_FONT);
    const double x0 = x - halign * (w10 + 0.5 + we);
    sus_plot_text(cr, x0, y, "10", TICK_FONT, 0.0, valign, 0);
    sus_plot_text(cr, x0 + w10 + 0.5, y - TICK_FONT * 0.42, ex, TICK_FONT, 0.0, valign, 0);
}

static double nice_step(double span)
{
    const double raw = span / 5.0, mag = pow(10.0, floor(log10(raw))), f = raw / mag;
    return (f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0) * mag;
}

static void tick_label(char *buf, size_t len, double v, double step)
{
    if (fabs(v) < 1e-9 * step)
        v = 0.0;
    const double a = fabs(v);
    if (v != 0.0 && (a < 1e-3 || a >= 1e5))
        snprintf(buf, len, "%.3g", v);
    else {
        const int dec = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
        snprintf(buf, len, "%.*f", dec, v);
    }
}

/* Draws the ticks of one axis (vertical = 0 for x, 1 for y). */
static void axis_ticks(const sus_plot_axes *ax, int vertical)
{
    cairo_t *cr = ax->cr;
    const int log = vertical ? ax->ylog : ax->xlog;
    const double lo = vertical ? ax->y0 : ax->x0, hi = vertical ? ax->y1 : ax->x1;
    const double major = 4.0, minor = 2.0;
    cairo_set_line_width(cr, 0.6);
    cairo_set_source_rgb(cr, 0, 0, 0);
    if (log) {
        const int e0 = (int)ceil(log10(lo) - 1e-9), e1 = (int)floor(log10(hi) + 1e-9);
        const int every = (e1 - e0) > 16 ? 4 : (e1 - e0) > 8 ? 2 : 1;
        for (int e = (int)floor(log10(lo)); e <= e1; e++) {
            for (int mnt = 1; mnt <= 9; mnt++) {
                const double v = mnt * pow(10.0, e);
                if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9) || (mnt > 1 && e1 - e0 > 6))
                    continue;
                const double len = mnt == 1 ? major : minor;
                if (vertical) {
                    const double py = map_y(ax, v);
                    cairo_move_to(cr, ax->x, py);
                    cairo_line_to(cr, ax->x + len, py);
                } else {
                    const double px = map_x(ax, v);
                    cairo_move_to(cr, px, ax->y + ax->h);
                    cairo_line_to(cr, px, ax->y + ax->h - len);
                }
                cairo_stroke(cr);
                if (mnt == 1 && (e - e0) % every == 0) {
                    if (vertical)
                        power_label(cr, ax->x - 3.0, map_y(ax, v), e, 1.0, 0.5);
                    else
                        power_label(cr, map_x(ax, v), ax->y + ax->h + 4.0, e, 0.5, 0.0);
                }
            }
        }
        return;
    }
    const double step = nice_step(hi - lo);
    for (double v = ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) {
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        if (vertical) {
            const double py = map_y(ax, v);
            cairo_move_to(cr, ax->x, py);
            cairo_line_to(cr, ax->x + major, py);
            cairo_stroke(cr);
            sus_plot_text(cr, ax->x - 3.0, py, buf, TICK_FONT, 1.0, 0.5, 0);
        } else {
            const double px = map_x(ax, v);
            cairo_move_to(cr, px, ax->y + ax->h);
            cairo_line_to(cr, px, ax->y + ax->h - major);
            cairo_stroke(cr);
            sus_plot_text(cr, px, ax->y + ax->h + 4.0, buf, TICK_FONT, 0.5, 0.0, 0);
        }
    }
}

void sus_plot_frame(const sus_plot_axes *ax, const char *xlabel, const char *ylabel, const char *letter)
{
    cairo_t *cr = ax->cr;
    cairo_save(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 0.8);
    cairo_rectangle(cr, ax->x, ax->y, ax->w, ax->h);
    cairo_stroke(cr);
    if (!ax->no_xticks)
        axis_ticks(ax, 0);
    axis_ticks(ax, 1);
    if (xlabel)
        sus_plot_text(cr, ax->x + 0.5 * ax->w, ax->y + ax->h + 16.0, xlabel, LABEL_FONT, 0.5, 0.0, 0);
    if (ylabel) {
        cairo_save(cr);
        cairo_translate(cr, ax->x - 40.0, ax->y + 0.5 * ax->h);
        cairo_rotate(cr, -PLOT_PI / 2.0);
        sus_plot_text(cr, 0.0, 0.0, ylabel, LABEL_FONT, 0.5, 0.5, 0);
        cairo_restore(cr);
    }
    if (letter) { /* above the frame, and above the y-label's top end when the label outgrows the frame */
        const double label_top = ylabel ? ax->y + 0.5 * (ax->h - text_width(cr, ylabel, LABEL_FONT)) : ax->y;
        const double base = fmin(ax->y, label_top - 2.0) - 6.0;
        sus_plot_text(cr, ax->x - 44.0, base, letter, LABEL_FONT + 1.0, 0.0, 1.0, 1);
    }
    cairo_restore(cr);
}

static void set_style(cairo_t *cr, const sus_plot_style *st)
{
    static const double dashed[] = {4.0, 2.5}, dotted[] = {1.0, 2.0};
    cairo_set_source_rgb(cr, st->r, st->g, st->b);
    cairo_set_line_width(cr, st->width > 0 ? st->width : 0.8);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    if (st->dash == 1)
        cairo_set_dash(cr, dashed, 2, 0.0);
    else if (st->dash == 2)
        cairo_set_dash(cr, dotted, 2, 0.0);
    else
        cairo_set_dash(cr, NULL, 0, 0.0);
}

static int visible(const sus_plot_axes *ax, double x, double y)
{
    return isfinite(x) && isfinite(y) && (!ax->xlog || x > 0.0) && (!ax->ylog || y > 0.0);
}

static void clip_to(const sus_plot_axes *ax)
{
    cairo_rectangle(ax->cr, ax->x, ax->y, ax->w, ax->h);
    cairo_clip(ax->cr);
}

static void marker(cairo_t *cr, int shape, double x, double y, double s)
{
    const double r = 0.5 * s;
    cairo_new_sub_path(cr);
    switch (shape) {
    case SUS_PLOT_DOT:
    case SUS_PLOT_CIRCLE:
        cairo_arc(cr, x, y, r, 0.0, 2.0 * PLOT_PI);
        break;
    case SUS_PLOT_SQUARE:
        cairo_rectangle(cr, x - r, y - r, s, s);
        break;
    case SUS_PLOT_TRIANGLE:
        cairo_move_to(cr, x, y - 1.15 * r);
        cairo_line_to(cr, x + r, y + 0.75 * r);
        cairo_line_to(cr, x - r, y + 0.75 * r);
        cairo_close_path(cr);
        break;
    case SUS_PLOT_DIAMOND:
        cairo_move_to(cr, x, y - 1.2 * r);
        cairo_line_to(cr, x + r, y);
        cairo_line_to(cr, x, y + 1.2 * r);
        cairo_line_to(cr, x - r, y);
        cairo_close_path(cr);
        break;
    case SUS_PLOT_CROSS:
        cairo_move_to(cr, x - r, y - r);
        cairo_line_to(cr, x + r, y + r);
        cairo_move_to(cr, x - r, y + r);
        cairo_line_to(cr, x + r, y - r);
        break;
    default:
        break;
    }
}

static void stroke_marker(cairo_t *cr, int shape)
{
    cairo_set_dash(cr, NULL, 0, 0.0);
    if (shape == SUS_PLOT_DOT)
        cairo_fill(cr);
    else {
        cairo_set_line_width(cr, 0.7);
        cairo_stroke(cr);
    }
}

void sus_plot_series(const sus_plot_axes *ax, const double *x, const double *y, size_t n, size_t stride,
                 const sus_plot_style *st)
{
    cairo_t *cr = ax->cr;
    if (st->width <= 0)
        return;
    cairo_save(cr);
    clip_to(ax);
    set_style(cr, st);
    int pen = 0;
    for (size_t i = 0; i < n; i++) {
        const double xv = x[i * stride], yv = y[i * stride];
        if (!visible(ax, xv, yv)) {
            pen = 0;
            continue;
        }
        if (pen)
            cairo_line_to(cr, map_x(ax, xv), map_y(ax, yv));
        else
            cairo_move_to(cr, map_x(ax, xv), map_y(ax, yv));
        pen = 1;
    }
    cairo_stroke(cr);
    cairo_restore(cr);
}

void sus_plot_markers(const sus_plot_axes *ax, const double *x, const double *y, size_t n, size_t every,
                  const sus_plot_style *st)
{
    cairo_t *cr = ax->cr;
    if (st->marker == SUS_PLOT_NONE)
        return;
    cairo_save(cr);
    clip_to(ax);
    set_style(cr, st);
    for (size_t i = 0; i < n; i += every ? every : 1) {
        if (!visible(ax, x[i], y[i]))
            continue;
        marker(cr, st->marker, map_x(ax, x[i]), map_y(ax, y[i]), st->size);
        stroke_marker(cr, st->marker);
    }
    cairo_restore(cr);
}

void sus_plot_rect(const sus_plot_axes *ax, double x0, double x1, double y0, double y1, const double rgb[3])
{
    cairo_t *cr = ax->cr;
    cairo_save(cr);
    clip_to(ax);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    const double px0 = map_x(ax, x0), px1 = map_x(ax, x1), py0 = map_y(ax, y0), py1 = map_y(ax, y1);
    cairo_rectangle(cr, fmin(px0, px1), fmin(py0, py1), fabs(px1 - px0), fabs(py1 - py0));
    cairo_fill(cr);
    cairo_restore(cr);
}

/* Its sample, its longest label and the padding. */
double sus_plot_legend_width(cairo_t *cr, const sus_plot_style *st, int n)
{
    double wmax = 0.0;
    for (int i = 0; i < n; i++)
        if (st[i].label)
            wmax = fmax(wmax, text_width(cr, st[i].label, LEGEND_FONT));
    return LEGEND_SAMPLE + 3 * LEGEND_PAD + wmax;
}

void sus_plot_legend(const sus_plot_axes *ax, const sus_plot_style *st, int n, int corner)
{
    cairo_t *cr = ax->cr;
    const double row = LEGEND_ROW, sample = LEGEND_SAMPLE, pad = LEGEND_PAD, fs = LEGEND_FONT;
    int rows = 0;
    for (int i = 0; i < n; i++)
        rows += st[i].label != NULL;
    if (rows == 0)
        return;
    const double bw = sus_plot_legend_width(cr, st, n), bh = rows * row + pad;
    const double bx = corner % 2 ? ax->x + ax->w - bw - 4.0 : ax->x + 4.0;
    const double by = corner < 2   ? ax->y + 4.0
                      : corner < 4 ? ax->y + ax->h - bh - 4.0
                                   : ax->y + 0.5 * (ax->h - bh);
    cairo_save(cr);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_rectangle(cr, bx, by, bw, bh);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr, 0.5);
    cairo_stroke(cr);
    int k = 0;
    for (int i = 0; i < n; i++) {
        if (!st[i].label)
            continue;
        const double cy = by + pad + (k + 0.5) * row;
        set_style(cr, &st[i]);
        if (st[i].width > 0) {
            cairo_move_to(cr, bx + pad, cy);
            cairo_line_to(cr, bx + pad + sample, cy);
            cairo_stroke(cr);
        }
        if (st[i].marker) {
            marker(cr, st[i].marker, bx + pad + 0.5 * sample, cy, st[i].size);
            stroke_marker(cr, st[i].marker);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        sus_plot_text(cr, bx + 2 * pad + sample, cy, st[i].label, fs, 0.0, 0.5, 0);
        k++;
    }
    cairo_restore(cr);
}

void sus_plot_legend_columns(cairo_t *cr, double x, double y, double w, const sus_plot_style *st, int n)
{
    const int half = (n + 1) / 2;
    sus_plot_axes la;
    sus_plot_axes_init(&la, cr, x, y, w / 2 - 16, 1, 0, 1, 0, 1, 0, 0);
    sus_plot_legend(&la, st, half, 0);
    sus_plot_axes_init(&la, cr, x + w / 2, y, w / 2 - 16, 1, 0, 1, 0, 1, 0, 0);
    sus_plot_legend(&la, st + half, n - half, 0);
}

void sus_plot_legend_packed(cairo_t *cr, double x, double y, const sus_plot_style *st, int n, int ncol)
{
    const int per = (n + ncol - 1) / ncol;
    for (int c = 0; c * per < n; c++) {
        const int k = n - c * per < per ? n - c * per : per;
        sus_plot_axes la; /* a box sized by its labels, starting at la.x (corner 0) */
        sus_plot_axes_init(&la, cr, x, y, 1, 1, 0, 1, 0, 1, 0, 0);
        sus_plot_legend(&la, st + c * per, k, 0);
        x += sus_plot_legend_width(cr, st + c * per, k) + 6.0;
    }
}

double sus_plot_legend_height(int rows) { return rows * LEGEND_ROW + LEGEND_PAD; }

int sus_plot_hidden_under(const sus_plot_axes *ax, const double *x, const double *ya, const double *yb,
                          size_t n, double tol)
{
    int common = 0;
    for (size_t i = 0; i < n; i++) {
        if (!visible(ax, x[i], ya[i]))
            continue;
        if (!visible(ax, x[i], yb[i]) || fabs(map_y(ax, ya[i]) - map_y(ax, yb[i])) > tol)
            return 0;
        common++;
    }
    return common > 0;
}

void sus_plot_slope(const sus_plot_axes *ax, double xa, double xb, double yb, double slope, const char *label)
{
    cairo_t *cr = ax->cr;
    const double ya = yb * pow(xa / xb, slope);
    cairo_save(cr);
    clip_to(ax);
    const sus_plot_style st = sus_plot_style_of(SUS_PLOT_GREY, 0.8, 1, SUS_PLOT_NONE, 0, NULL);
    set_style(cr, &st);
    cairo_move_to(cr, map_x(ax, xa), map_y(ax, ya));
    cairo_line_to(cr, map_x(ax, xb), map_y(ax, yb));
    cairo_stroke(cr);
    if (label) { /* at the left end, so that segments sharing a right end keep apart */
        cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
        sus_plot_text(cr, map_x(ax, xa) - 2.0, map_y(ax, ya), label, TICK_FONT, 1.0, 0.5, 0);
    }
    cairo_restore(cr);
}

/* ---- output ---- */

/* Cairo writes through the atomic file (src/util/atomic_file.h): all or nothing, and no temporary
 * left behind even when the program is killed. */
static cairo_status_t write_to(void *fp, const unsigned char *data, unsigned int len)
{
    return fwrite(data, 1, len, fp) == len ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

static void paint_page(cairo_t *cr, void (*draw)(cairo_t *, void *), void *ctx)
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    draw(cr, ctx);
}

static cairo_status_t draw_pdf(FILE *fp, double width, double height, void (*draw)(cairo_t *, void *),
                               void *ctx)
{
    cairo_surface_t *pdf = cairo_pdf_surface_create_for_stream(write_to, fp, width, height);
    cairo_pdf_surface_set_metadata(pdf, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
    cairo_pdf_surface_set_metadata(pdf, CAIRO_PDF_METADATA_MOD_DATE, "2000-01-01T00:00:00Z");
    cairo_pdf_surface_set_metadata(pdf, CAIRO_PDF_METADATA_CREATOR, "suslov companion (Cairo)");
    cairo_t *cr = cairo_create(pdf);
    paint_page(cr, draw, ctx);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(pdf);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_status(pdf);
    cairo_surface_destroy(pdf);
    return st;
}

/* At SUS_PLOT_PNG_DPI. */
static cairo_status_t draw_png(FILE *fp, double width, double height, void (*draw)(cairo_t *, void *),
                               void *ctx)
{
    const double s = SUS_PLOT_PNG_DPI / 72.0;
    cairo_surface_t *img =
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)ceil(width * s), (int)ceil(height * s));
    cairo_t *cr = cairo_create(img);
    cairo_scale(cr, s, s);
    paint_page(cr, draw, ctx);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_write_to_png_stream(img, write_to, fp);
    cairo_surface_destroy(img);
    return st;
}

typedef cairo_status_t (*page_writer)(FILE *, double, double, void (*)(cairo_t *, void *), void *);

static int write_one(const char *path, page_writer wr, double width, double height,
                     void (*draw)(cairo_t *, void *), void *ctx, char *err, size_t errlen)
{
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, errlen) != 0)
        return -1;
    const cairo_status_t st = wr(af.fp, width, height, draw, ctx);
    if (st != CAIRO_STATUS_SUCCESS) {
        sus_sys_atomic_file_abort(&af);
        snprintf(err, errlen, "writing %s failed: %s", path, cairo_status_to_string(st));
        return -1;
    }
    return sus_sys_atomic_file_commit(&af, err, errlen);
}

int sus_plot_write_surface_png(cairo_surface_t *s, const char *path, char *err, size_t errlen)
{
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, errlen) != 0)
        return -1;
    const cairo_status_t st = cairo_surface_write_to_png_stream(s, write_to, af.fp);
    if (st != CAIRO_STATUS_SUCCESS) {
        sus_sys_atomic_file_abort(&af);
        snprintf(err, errlen, "writing %s failed: %s", path, cairo_status_to_string(st));
        return -1;
    }
    return sus_sys_atomic_file_commit(&af, err, errlen);
}

int sus_plot_write(const char *base, double width, double height, void (*draw)(cairo_t *, void *),
               void *ctx, char *err, size_t errlen)
{
    char path[4096];
    snprintf(path, sizeof path, "%s.pdf", base);
    if (write_one(path, draw_pdf, width, height, draw, ctx, err, errlen) != 0)
        return -1;
    snprintf(path, sizeof path, "%s.png", base);
    return write_one(path, draw_png, width, height, draw, ctx, err, errlen);
}
