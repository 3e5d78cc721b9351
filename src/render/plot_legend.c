#include "plot_internal.h"

#include <math.h>

#define LEGEND_ROW 11.0 /* a legend line, and the padding of its box */
#define LEGEND_PAD 4.0
#define LEGEND_SAMPLE 18.0
#define LEGEND_FONT SUS_PLOT_MIN_FONT

/* Its sample, its longest label and the padding. */
double sus_plot_legend_width(cairo_t *cr, const sus_plot_style *st, int n)
{
    double wmax = 0.0;
    for (int i = 0; i < n; i++)
        if (st[i].label)
            wmax = fmax(wmax, sus_plot_text_width(cr, st[i].label, LEGEND_FONT));
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
        sus_plot_set_style(cr, &st[i]);
        if (st[i].width > 0) {
            cairo_move_to(cr, bx + pad, cy);
            cairo_line_to(cr, bx + pad + sample, cy);
            cairo_stroke(cr);
        }
        if (st[i].marker) {
            sus_plot_marker_path(cr, st[i].marker, bx + pad + 0.5 * sample, cy, st[i].size);
            sus_plot_marker_stroke(cr, st[i].marker);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        sus_plot_text(cr, bx + 2 * pad + sample, cy, st[i].label, fs, 0.0, 0.5, 0);
        k++;
    }
    cairo_restore(cr);
}

void sus_plot_legend_columns(cairo_t *cr, double x, double y, double w, const sus_plot_style *st,
                             int n)
{
    const int half = (n + 1) / 2;
    sus_plot_axes la;
    sus_plot_axes_init(&la, cr, x, y, w / 2 - 16, 1, 0, 1, 0, 1, 0, 0);
    sus_plot_legend(&la, st, half, 0);
    sus_plot_axes_init(&la, cr, x + w / 2, y, w / 2 - 16, 1, 0, 1, 0, 1, 0, 0);
    sus_plot_legend(&la, st + half, n - half, 0);
}

void sus_plot_legend_packed(cairo_t *cr, double x, double y, const sus_plot_style *st, int n,
                            int ncol)
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
