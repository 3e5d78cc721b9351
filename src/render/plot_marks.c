#include "plot_internal.h"

#include <math.h>

void sus_plot_set_style(cairo_t *cr, const sus_plot_style *st)
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

void sus_plot_marker_path(cairo_t *cr, int shape, double x, double y, double s)
{
    const double r = 0.5 * s;
    cairo_new_sub_path(cr);
    switch (shape) {
        case SUS_PLOT_DOT:
        case SUS_PLOT_CIRCLE: cairo_arc(cr, x, y, r, 0.0, 2.0 * SUS_PLOT_PI); break;
        case SUS_PLOT_SQUARE: cairo_rectangle(cr, x - r, y - r, s, s); break;
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
        default: break;
    }
}

void sus_plot_marker_stroke(cairo_t *cr, int shape)
{
    cairo_set_dash(cr, NULL, 0, 0.0);
    if (shape == SUS_PLOT_DOT)
        cairo_fill(cr);
    else {
        cairo_set_line_width(cr, 0.7);
        cairo_stroke(cr);
    }
}

void sus_plot_series(const sus_plot_axes *ax, const double *x, const double *y, size_t n,
                     size_t stride, const sus_plot_style *st)
{
    cairo_t *cr = ax->cr;
    if (st->width <= 0)
        return;
    cairo_save(cr);
    clip_to(ax);
    sus_plot_set_style(cr, st);
    int pen = 0;
    for (size_t i = 0; i < n; i++) {
        const double xv = x[i * stride], yv = y[i * stride];
        if (!visible(ax, xv, yv)) {
            pen = 0;
            continue;
        }
        if (pen)
            cairo_line_to(cr, sus_plot_map_x(ax, xv), sus_plot_map_y(ax, yv));
        else
            cairo_move_to(cr, sus_plot_map_x(ax, xv), sus_plot_map_y(ax, yv));
        pen = 1;
    }
    cairo_stroke(cr);
    cairo_restore(cr);
}

void sus_plot_markers(const sus_plot_axes *ax, const double *x, const double *y, size_t n,
                      size_t every, const sus_plot_style *st)
{
    cairo_t *cr = ax->cr;
    if (st->marker == SUS_PLOT_NONE)
        return;
    cairo_save(cr);
    clip_to(ax);
    sus_plot_set_style(cr, st);
    for (size_t i = 0; i < n; i += every ? every : 1) {
        if (!visible(ax, x[i], y[i]))
            continue;
        sus_plot_marker_path(cr, st->marker, sus_plot_map_x(ax, x[i]), sus_plot_map_y(ax, y[i]),
                             st->size);
        sus_plot_marker_stroke(cr, st->marker);
    }
    cairo_restore(cr);
}

void sus_plot_rect(const sus_plot_axes *ax, double x0, double x1, double y0, double y1,
                   const double rgb[3])
{
    cairo_t *cr = ax->cr;
    cairo_save(cr);
    clip_to(ax);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    const double px0 = sus_plot_map_x(ax, x0), px1 = sus_plot_map_x(ax, x1),
                 py0 = sus_plot_map_y(ax, y0), py1 = sus_plot_map_y(ax, y1);
    cairo_rectangle(cr, fmin(px0, px1), fmin(py0, py1), fabs(px1 - px0), fabs(py1 - py0));
    cairo_fill(cr);
    cairo_restore(cr);
}

void sus_plot_band(const sus_plot_axes *ax, const double *x, const double *lo, const double *hi,
                   size_t n, const double rgb[3])
{
    cairo_t *cr = ax->cr;
    cairo_save(cr);
    clip_to(ax);
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_new_path(cr);
    for (size_t i = 0; i < n; i++) /* along hi, then back along lo */
        if (visible(ax, x[i], hi[i]) && visible(ax, x[i], lo[i]))
            cairo_line_to(cr, sus_plot_map_x(ax, x[i]), sus_plot_map_y(ax, hi[i]));
    for (size_t i = n; i-- > 0;)
        if (visible(ax, x[i], hi[i]) && visible(ax, x[i], lo[i]))
            cairo_line_to(cr, sus_plot_map_x(ax, x[i]), sus_plot_map_y(ax, lo[i]));
    cairo_close_path(cr);
    cairo_fill(cr);
    cairo_restore(cr);
}

int sus_plot_hidden_under(const sus_plot_axes *ax, const double *x, const double *ya,
                          const double *yb, size_t n, double tol)
{
    int common = 0;
    for (size_t i = 0; i < n; i++) {
        if (!visible(ax, x[i], ya[i]))
            continue;
        if (!visible(ax, x[i], yb[i]) ||
            fabs(sus_plot_map_y(ax, ya[i]) - sus_plot_map_y(ax, yb[i])) > tol)
            return 0;
        common++;
    }
    return common > 0;
}

void sus_plot_slope(const sus_plot_axes *ax, double xa, double xb, double yb, double slope,
                    const char *label)
{
    cairo_t *cr = ax->cr;
    const double ya = yb * pow(xa / xb, slope);
    cairo_save(cr);
    clip_to(ax);
    const sus_plot_style st = sus_plot_style_of(SUS_PLOT_GREY, 0.8, 1, SUS_PLOT_NONE, 0, NULL);
    sus_plot_set_style(cr, &st);
    cairo_move_to(cr, sus_plot_map_x(ax, xa), sus_plot_map_y(ax, ya));
    cairo_line_to(cr, sus_plot_map_x(ax, xb), sus_plot_map_y(ax, yb));
    cairo_stroke(cr);
    if (label) { /* at the left end, so that segments sharing a right end keep apart */
        cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
        sus_plot_text(cr, sus_plot_map_x(ax, xa) - 2.0, sus_plot_map_y(ax, ya), label,
                      SUS_PLOT_TICK_FONT, 1.0, 0.5, 0);
    }
    cairo_restore(cr);
}
