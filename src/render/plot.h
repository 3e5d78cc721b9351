/* A small plotting layer on Cairo, shared by every figure: panels with linear or log axes,
 * nice-number ticks (log decades with minor ticks), lines, sub-sampled markers, legends,
 * reference-slope segments and panel letters. One drawing routine renders a page; plot_write
 * sends it to a vector PDF and a 150 dpi PNG, each written all-or-nothing. */
#ifndef SUSLOV_PLOT_H
#define SUSLOV_PLOT_H

#include <cairo.h>
#include <stddef.h>

#define PLOT_FONT "DejaVu Sans"
#define PLOT_PNG_DPI 150.0

typedef struct {
    cairo_t *cr;
    double x, y, w, h;      /* plot area on the page, points */
    double x0, x1, y0, y1;  /* data range */
    int xlog, ylog;
    int no_xticks;  /* categories on x (a bar chart): no numeric ticks */
} plot_axes;

enum { PLOT_NONE = 0, PLOT_DOT, PLOT_CIRCLE, PLOT_SQUARE, PLOT_TRIANGLE, PLOT_DIAMOND, PLOT_CROSS };

typedef struct {
    double r, g, b;
    double width;      /* line width in points, 0 for no line */
    int dash;          /* 0 solid, 1 dashed, 2 dotted */
    int marker;        /* PLOT_* */
    double size;       /* marker size in points */
    const char *label; /* legend text, NULL for none */
} plot_style;

/* The colours of the paper's Figure 2 and a few more, colour-blind distinguishable. */
extern const double PLOT_RED[3], PLOT_BLUE[3], PLOT_GREEN[3], PLOT_ORANGE[3], PLOT_PURPLE[3],
    PLOT_GREY[3], PLOT_BLACK[3];
/* Colours for one curve per method: Okabe-Ito first (told apart by colour-blind readers), then
 * dark red, black, brown, slate blue, dark green and olive, and no grey (reference curves are
 * grey); markers tell the rest apart. Curve i takes PLOT_PALETTE[i % PLOT_PALETTE_N]. */
#define PLOT_PALETTE_N 12
extern const double PLOT_PALETTE[PLOT_PALETTE_N][3];
plot_style plot_style_of(const double rgb[3], double width, int dash, int marker, double size,
                         const char *label);

/* Grows [*lo, *hi] to hold the finite values (positive ones only when log) of v[0], v[stride],... */
void plot_extend(double *lo, double *hi, const double *v, size_t n, size_t stride, int log);
/* Pads a linear range by 5% (and widens an empty one), or a log range to whole decades. */
void plot_pad(double *lo, double *hi, int log);

/* The plot area of panel idx (row-major) in a rows x cols grid on a page of width x height
 * points, with room left for tick labels, axis labels, panel letters and a title line. */
void plot_cell(double width, double height, int rows, int cols, int idx, double *x, double *y,
               double *w, double *h);
/* Sets up the panel at grid cell idx with the data ranges padded by plot_pad. */
void plot_axes_cell(plot_axes *ax, cairo_t *cr, double width, double height, int rows, int cols,
                    int idx, double x0, double x1, double y0, double y1, int xlog, int ylog);

void plot_axes_init(plot_axes *ax, cairo_t *cr, double x, double y, double w, double h,
                    double x0, double x1, double y0, double y1, int xlog, int ylog);
/* Frame, ticks, tick labels, axis labels and the panel letter "(a)" at the top left. */
void plot_frame(const plot_axes *ax, const char *xlabel, const char *ylabel, const char *letter);
void plot_series(const plot_axes *ax, const double *x, const double *y, size_t n, size_t stride,
                 const plot_style *st);
/* Markers only, at every `every`-th point (so 10^5 points do not become a smear). */
void plot_markers(const plot_axes *ax, const double *x, const double *y, size_t n, size_t every,
                  const plot_style *st);
/* A filled rectangle [x0, x1] x [y0, y1] in data coordinates (a cell of a map), clipped. */
void plot_rect(const plot_axes *ax, double x0, double x1, double y0, double y1, const double rgb[3]);
/* A legend box: 0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right, 4 middle-left,
 * 5 middle-right. */
void plot_legend(const plot_axes *ax, const plot_style *st, int n, int corner);
/* A dashed grey segment of slope `slope` in log-log axes from xa to (xb, yb), labelled at xa. */
void plot_slope(const plot_axes *ax, double xa, double xb, double yb, double slope, const char *label);
void plot_text(cairo_t *cr, double x, double y, const char *text, double size, double halign,
               double valign, int bold);

/* Renders draw(cr, ctx) on a width x height point page into base.pdf and base.png. Returns 0,
 * or -1 with a one-line reason. The PDF carries a fixed creation date so that it is
 * reproducible byte for byte. */
/* An image surface as a PNG file, through the atomic file (src/util/atomic_file.h). */
int plot_write_surface_png(cairo_surface_t *s, const char *path, char *err, size_t errlen);
int plot_write(const char *base, double width, double height, void (*draw)(cairo_t *, void *),
               void *ctx, char *err, size_t errlen);

#endif
