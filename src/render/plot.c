#include "plot_internal.h"

#include <math.h>
#include <stdio.h>

const double SUS_PLOT_PALETTE[SUS_PLOT_PALETTE_N][3] = {
    {0.90, 0.62, 0.00}, {0.00, 0.62, 0.45}, {0.80, 0.47, 0.65}, {0.00, 0.45, 0.70},
    {0.84, 0.37, 0.00}, {0.34, 0.71, 0.91}, {0.60, 0.10, 0.15}, {0.20, 0.20, 0.20},
    {0.55, 0.35, 0.10}, {0.40, 0.40, 0.85}, {0.10, 0.40, 0.20}, {0.65, 0.65, 0.00},
    {0.85, 0.15, 0.65}};
const double SUS_PLOT_RED[3] = {0.85, 0.15, 0.10}, SUS_PLOT_BLUE[3] = {0.12, 0.35, 0.80},
             SUS_PLOT_GREEN[3] = {0.10, 0.60, 0.20}, SUS_PLOT_ORANGE[3] = {0.95, 0.55, 0.05},
             SUS_PLOT_PURPLE[3] = {0.55, 0.25, 0.70}, SUS_PLOT_GREY[3] = {0.45, 0.45, 0.45},
             SUS_PLOT_BLACK[3] = {0.0, 0.0, 0.0};

#define LABEL_FONT 10.0

sus_plot_style sus_plot_style_of(const double rgb[3], double width, int dash, int marker,
                                 double size, const char *label)
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

void sus_plot_axes_cell(sus_plot_axes *ax, cairo_t *cr, double width, double height, int rows,
                        int cols, int idx, double x0, double x1, double y0, double y1, int xlog,
                        int ylog)
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

double sus_plot_map_x(const sus_plot_axes *ax, double v)
{
    return ax->x + (tx(v, ax->xlog) - tx(ax->x0, ax->xlog)) /
                       (tx(ax->x1, ax->xlog) - tx(ax->x0, ax->xlog)) * ax->w;
}

double sus_plot_map_y(const sus_plot_axes *ax, double v)
{
    return ax->y + ax->h -
           (tx(v, ax->ylog) - tx(ax->y0, ax->ylog)) /
               (tx(ax->y1, ax->ylog) - tx(ax->y0, ax->ylog)) * ax->h;
}

/* "10" with a raised exponent, aligned like sus_plot_text. The exponent keeps the tick size, the
 * smallest that stays legible in print (SUS_PLOT_MIN_FONT). */
static void power_label(cairo_t *cr, double x, double y, int e, double halign, double valign)
{
    char ex[16];
    snprintf(ex, sizeof ex, "%d", e);
    const double w10 = sus_plot_text_width(cr, "10", SUS_PLOT_TICK_FONT),
                 we = sus_plot_text_width(cr, ex, SUS_PLOT_TICK_FONT);
    const double x0 = x - halign * (w10 + 0.5 + we);
    sus_plot_text(cr, x0, y, "10", SUS_PLOT_TICK_FONT, 0.0, valign, 0);
    sus_plot_text(cr, x0 + w10 + 0.5, y - SUS_PLOT_TICK_FONT * 0.42, ex, SUS_PLOT_TICK_FONT, 0.0,
                  valign, 0);
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

/* The ticks of a log axis (vertical = 0 for x, 1 for y) over [lo, hi]: every decade labelled
 * (every second or fourth over many decades), minor ticks when it spans few. */
static void log_ticks(const sus_plot_axes *ax, int vertical, double lo, double hi)
{
    cairo_t *cr = ax->cr;
    const double major = 4.0, minor = 2.0;
    const int e0 = (int)ceil(log10(lo) - 1e-9), e1 = (int)floor(log10(hi) + 1e-9);
    const int every = (e1 - e0) > 16 ? 4 : (e1 - e0) > 8 ? 2 : 1;
    for (int e = (int)floor(log10(lo)); e <= e1; e++) {
        for (int mnt = 1; mnt <= 9; mnt++) {
            const double v = mnt * pow(10.0, e);
            if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9) || (mnt > 1 && e1 - e0 > 6))
                continue;
            const double len = mnt == 1 ? major : minor;
            if (vertical) {
                const double py = sus_plot_map_y(ax, v);
                cairo_move_to(cr, ax->x, py);
                cairo_line_to(cr, ax->x + len, py);
            } else {
                const double px = sus_plot_map_x(ax, v);
                cairo_move_to(cr, px, ax->y + ax->h);
                cairo_line_to(cr, px, ax->y + ax->h - len);
            }
            cairo_stroke(cr);
            if (mnt == 1 && (e - e0) % every == 0) {
                if (vertical)
                    power_label(cr, ax->x - 3.0, sus_plot_map_y(ax, v), e, 1.0, 0.5);
                else
                    power_label(cr, sus_plot_map_x(ax, v), ax->y + ax->h + 4.0, e, 0.5, 0.0);
            }
        }
    }
}

/* The ticks of a linear axis over [lo, hi], at a nice step, each labelled. */
static void linear_ticks(const sus_plot_axes *ax, int vertical, double lo, double hi)
{
    cairo_t *cr = ax->cr;
    const double major = 4.0;
    const double step = nice_step(hi - lo);
    for (double v = ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) {
        char buf[32];
        tick_label(buf, sizeof buf, v, step);
        if (vertical) {
            const double py = sus_plot_map_y(ax, v);
            cairo_move_to(cr, ax->x, py);
            cairo_line_to(cr, ax->x + major, py);
            cairo_stroke(cr);
            sus_plot_text(cr, ax->x - 3.0, py, buf, SUS_PLOT_TICK_FONT, 1.0, 0.5, 0);
        } else {
            const double px = sus_plot_map_x(ax, v);
            cairo_move_to(cr, px, ax->y + ax->h);
            cairo_line_to(cr, px, ax->y + ax->h - major);
            cairo_stroke(cr);
            sus_plot_text(cr, px, ax->y + ax->h + 4.0, buf, SUS_PLOT_TICK_FONT, 0.5, 0.0, 0);
        }
    }
}

/* Draws the ticks of one axis (vertical = 0 for x, 1 for y). */
static void axis_ticks(const sus_plot_axes *ax, int vertical)
{
    const int log = vertical ? ax->ylog : ax->xlog;
    const double lo = vertical ? ax->y0 : ax->x0, hi = vertical ? ax->y1 : ax->x1;
    cairo_set_line_width(ax->cr, 0.6);
    cairo_set_source_rgb(ax->cr, 0, 0, 0);
    if (log)
        log_ticks(ax, vertical, lo, hi);
    else
        linear_ticks(ax, vertical, lo, hi);
}

void sus_plot_frame(const sus_plot_axes *ax, const char *xlabel, const char *ylabel,
                    const char *letter)
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
        sus_plot_text(cr, ax->x + 0.5 * ax->w, ax->y + ax->h + 16.0, xlabel, LABEL_FONT, 0.5, 0.0,
                      0);
    if (ylabel) {
        cairo_save(cr);
        cairo_translate(cr, ax->x - 40.0, ax->y + 0.5 * ax->h);
        cairo_rotate(cr, -SUS_PLOT_PI / 2.0);
        sus_plot_text(cr, 0.0, 0.0, ylabel, LABEL_FONT, 0.5, 0.5, 0);
        cairo_restore(cr);
    }
    /* the letter above the frame, and above the y-label's top end when the label outgrows it */
    if (letter) {
        const double label_top =
            ylabel ? ax->y + 0.5 * (ax->h - sus_plot_text_width(cr, ylabel, LABEL_FONT)) : ax->y;
        const double base = fmin(ax->y, label_top - 2.0) - 6.0;
        sus_plot_text(cr, ax->x - 44.0, base, letter, LABEL_FONT + 1.0, 0.0, 1.0, 1);
    }
    cairo_restore(cr);
}
