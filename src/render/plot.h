/* A small plotting layer on Cairo, shared by every figure: panels with linear or log axes,
 * nice-number ticks (log decades with minor ticks), lines, sub-sampled markers, legends,
 * reference-slope segments and panel letters. One drawing routine renders a page; sus_plot_write
 * sends it to a vector PDF and a 150 dpi PNG, each written all-or-nothing. Its parts: plot.c
 * (ranges, panels, ticks, frames), plot_text.c (labels with scripts), plot_marks.c (lines,
 * markers, cells, slopes), plot_legend.c, plot_write.c (the PDF and PNG files). */
#ifndef SUS_PLOT_PLOT_H
#define SUS_PLOT_PLOT_H

#include <cairo.h>
#include <stddef.h>

#define SUS_PLOT_FONT "DejaVu Sans"
#define SUS_PLOT_PNG_DPI 150.0
/* The companion prints a figure at SUS_PLOT_PRINT_SCALE of its size (\FigScale in
 * paper/preamble.tex), and no text may print below 7 pt: so no text is drawn below
 * SUS_PLOT_MIN_FONT, scripts included. tools/paper_fontsize.sh checks the printed PDFs. */
#define SUS_PLOT_PRINT_SCALE 0.875
#define SUS_PLOT_MIN_FONT (7.0 / SUS_PLOT_PRINT_SCALE)

typedef struct {
    cairo_t *cr;
    double x, y, w, h;     /* plot area on the page, points */
    double x0, x1, y0, y1; /* data range */
    int xlog, ylog;
    int no_xticks; /* categories on x (a bar chart): no numeric ticks */
} sus_plot_axes;

enum {
    SUS_PLOT_NONE = 0,
    SUS_PLOT_DOT,
    SUS_PLOT_CIRCLE,
    SUS_PLOT_SQUARE,
    SUS_PLOT_TRIANGLE,
    SUS_PLOT_DIAMOND,
    SUS_PLOT_CROSS
};

typedef struct {
    double r, g, b;
    double width;      /* line width in points, 0 for no line */
    int dash;          /* 0 solid, 1 dashed, 2 dotted */
    int marker;        /* PLOT_* */
    double size;       /* marker size in points */
    const char *label; /* legend text, NULL for none */
} sus_plot_style;

/* The colours of the paper's Figure 2 and a few more, colour-blind distinguishable. */
extern const double SUS_PLOT_RED[3], SUS_PLOT_BLUE[3], SUS_PLOT_GREEN[3], SUS_PLOT_ORANGE[3],
    SUS_PLOT_PURPLE[3], SUS_PLOT_GREY[3], SUS_PLOT_BLACK[3];
/* Colours for one curve per method: Okabe-Ito first (told apart by colour-blind readers), then
 * dark red, black, brown, slate blue, dark green, olive and magenta (one colour for each of the
 * thirteen methods of a convergence figure), and no grey (reference curves are grey); markers
 * tell the rest apart. Curve i takes SUS_PLOT_PALETTE[i % SUS_PLOT_PALETTE_N]. */
#define SUS_PLOT_PALETTE_N 13
extern const double SUS_PLOT_PALETTE[SUS_PLOT_PALETTE_N][3];
sus_plot_style sus_plot_style_of(const double rgb[3], double width, int dash, int marker,
                                 double size, const char *label);

/* Grows [*lo, *hi] to hold the finite values (positive ones only when log) of v[0], v[stride],...
 */
void sus_plot_extend(double *lo, double *hi, const double *v, size_t n, size_t stride, int log);
/* Pads a linear range by 5% (and widens an empty one), or a log range to whole decades. */
void sus_plot_pad(double *lo, double *hi, int log);

/* The plot area of panel idx (row-major) in a rows x cols grid on a page of width x height
 * points, with room left for tick labels, axis labels, panel letters and a title line. */
void sus_plot_cell(double width, double height, int rows, int cols, int idx, double *x, double *y,
                   double *w, double *h);
/* Sets up the panel at grid cell idx with the data ranges padded by sus_plot_pad. */
void sus_plot_axes_cell(sus_plot_axes *ax, cairo_t *cr, double width, double height, int rows,
                        int cols, int idx, double x0, double x1, double y0, double y1, int xlog,
                        int ylog);

void sus_plot_axes_init(sus_plot_axes *ax, cairo_t *cr, double x, double y, double w, double h,
                        double x0, double x1, double y0, double y1, int xlog, int ylog);
/* Frame, ticks, tick labels, axis labels and the panel letter "(a)" at the top left. */
void sus_plot_frame(const sus_plot_axes *ax, const char *xlabel, const char *ylabel,
                    const char *letter);
void sus_plot_series(const sus_plot_axes *ax, const double *x, const double *y, size_t n,
                     size_t stride, const sus_plot_style *st);
/* Markers only, at every `every`-th point (so 10^5 points do not become a smear). */
void sus_plot_markers(const sus_plot_axes *ax, const double *x, const double *y, size_t n,
                      size_t every, const sus_plot_style *st);
/* A filled rectangle [x0, x1] x [y0, y1] in data coordinates (a cell of a map), clipped. */
void sus_plot_rect(const sus_plot_axes *ax, double x0, double x1, double y0, double y1,
                   const double rgb[3]);
/* The region between the curves (x, lo) and (x, hi), filled, clipped; points that are not
 * visible on the axes (a zero on a log axis, a NaN) are left out. */
void sus_plot_band(const sus_plot_axes *ax, const double *x, const double *lo, const double *hi,
                   size_t n, const double rgb[3]);
/* A legend box: 0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right, 4 middle-left,
 * 5 middle-right. */
void sus_plot_legend(const sus_plot_axes *ax, const sus_plot_style *st, int n, int corner);
/* The legend of a figure in two columns below its panels, each half of width w from x, top at y:
 * a portrait page has room for one long legend only side by side. */
void sus_plot_legend_columns(cairo_t *cr, double x, double y, double w, const sus_plot_style *st,
                             int n);
/* A legend in ncol boxes side by side from (x, y), filled column by column, each as wide as its
 * labels; and the height of a legend of `rows` lines. */
void sus_plot_legend_packed(cairo_t *cr, double x, double y, const sus_plot_style *st, int n,
                            int ncol);
double sus_plot_legend_height(int rows);
/* The width of a legend box of these entries, as sus_plot_legend draws it. */
double sus_plot_legend_width(cairo_t *cr, const sus_plot_style *st, int n);
/* Whether the curve (x, ya), drawn first, hides under (x, yb): every point of it that the axes show
 * lies within tol points of yb's on the page. */
int sus_plot_hidden_under(const sus_plot_axes *ax, const double *x, const double *ya,
                          const double *yb, size_t n, double tol);
/* A dashed grey segment of slope `slope` in log-log axes from xa to (xb, yb), labelled at xa. */
void sus_plot_slope(const sus_plot_axes *ax, double xa, double xb, double yb, double slope,
                    const char *label);
void sus_plot_text(cairo_t *cr, double x, double y, const char *text, double size, double halign,
                   double valign, int bold);

/* Renders draw(cr, ctx) on a width x height point page into base.pdf and base.png. Returns 0,
 * or -1 with a one-line reason. The PDF carries a fixed creation date so that it is
 * reproducible byte for byte. */
/* An image surface as a PNG file, through the atomic file (src/util/atomic_file.h). */
int sus_plot_write_surface_png(cairo_surface_t *s, const char *path, char *err, size_t errlen);
int sus_plot_write(const char *base, double width, double height, void (*draw)(cairo_t *, void *),
                   void *ctx, char *err, size_t errlen);

#endif
