/* The text outputs of a figure program, each written all-or-nothing: the data behind the
 * panels as CSV (one header line, %.17g numbers) and the caption file. */
#ifndef SUS_PLOT_FIG_OUTPUT_H
#define SUS_PLOT_FIG_OUTPUT_H

#include <cairo.h>
#include <stddef.h>

/* Writes nrows rows of ncols columns; column c of row r is cols[c][r * every]. Returns 0, or
 * -1 with a message on stderr. */
int sus_plot_fig_write_csv(const char *path, const char *header, int ncols,
                           const double *const *cols, size_t nrows, size_t every);
int sus_plot_fig_write_text(const char *path, const char *text);
/* The figure DIR/NAME.pdf and DIR/NAME.png drawn by draw(cr, ctx) on a width x height point page,
 * and its caption DIR/NAME.txt. Returns 0, or -1 with a message on stderr. */
int sus_plot_fig_write_figure(const char *dir, const char *name, double width, double height,
                              void (*draw)(cairo_t *, void *), void *ctx, const char *caption);

/* "DIR/NAME.EXT" into buf. */
const char *sus_plot_fig_path(char *buf, size_t len, const char *dir, const char *name,
                              const char *ext);

#endif
