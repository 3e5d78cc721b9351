/* What the files of the plotting layer share: the mapping of data to the page (plot.c), the
 * width of a label (plot_text.c), line styles and markers (plot_marks.c), for the legends
 * (plot_legend.c) and the reference slopes. Figures use plot.h. */
#ifndef SUS_PLOT_INTERNAL_H
#define SUS_PLOT_INTERNAL_H

#include "plot.h"

#define SUS_PLOT_PI 3.14159265358979323846
#define SUS_PLOT_TICK_FONT SUS_PLOT_MIN_FONT

/* The page coordinates of a data value on the axes (log or linear as the axis is). */
double sus_plot_map_x(const sus_plot_axes *ax, double v);
double sus_plot_map_y(const sus_plot_axes *ax, double v);
/* The width of a label at a size (its scripts set as sus_plot_text sets them), for layout. */
double sus_plot_text_width(cairo_t *cr, const char *text, double size);
/* A style's colour, line width and dashes, set on cr. */
void sus_plot_set_style(cairo_t *cr, const sus_plot_style *st);
/* The path of a marker of shape SUS_PLOT_* at (x, y), s points across; then its stroke (a dot is
 * filled). */
void sus_plot_marker_path(cairo_t *cr, int shape, double x, double y, double s);
void sus_plot_marker_stroke(cairo_t *cr, int shape);

#endif
