/* The figures' legend notes: sus_plot_hidden_under says a curve hides under another exactly when
 * every point it draws lies within the tolerance of the other's on the page. On log axes of 10
 * points per decade, a factor 1 + 1e-3 moves a point by 10 log10(1.001) = 0.004 pt (hidden at
 * 1.5 pt) and a factor 1.5 by 1.8 pt (not hidden); a point the other curve does not draw, or a
 * curve that draws nothing, is never hidden. No text, scripts included, is set below the size that
 * prints at 7 pt. */
#include "check.h"
#include "plot.h"

#include <math.h>

#define N 8

int main(void)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 200, 200);
    cairo_t *cr = cairo_create(s);
    sus_plot_axes ax;
    sus_plot_axes_init(&ax, cr, 10, 10, 150, 100, 1e-3, 1.0, 1e-10, 1.0, 1, 1);
    double x[N], b[N], near[N], wider[N], gap[N], none[N];
    for (int i = 0; i < N; i++) {
        x[i] = pow(10.0, -3.0 + 3.0 * i / (N - 1));
        b[i] = 1e-9 * pow(10.0, i);
        near[i] = b[i] * (1.0 + 1e-3);
        wider[i] = b[i] * (i == N / 2 ? 1.5 : 1.0);
        gap[i] = b[i];
        none[i] = NAN;
    }
    double bgap[N];
    for (int i = 0; i < N; i++)
        bgap[i] = i == 3 ? NAN : b[i];
    CHECK(sus_plot_hidden_under(&ax, x, near, b, N, 1.5) == 1,
          "a factor 1 + 1e-3 hides under the curve");
    CHECK(sus_plot_hidden_under(&ax, x, b, b, N, 1.5) == 1, "a curve hides under itself");
    CHECK(sus_plot_hidden_under(&ax, x, wider, b, N, 1.5) == 0,
          "one point a factor 1.5 away (1.8 pt) shows");
    CHECK(sus_plot_hidden_under(&ax, x, wider, b, N, 2.0) == 1, "the same within a 2 pt tolerance");
    CHECK(sus_plot_hidden_under(&ax, x, gap, bgap, N, 1.5) == 0,
          "a point the other curve does not draw shows");
    CHECK(sus_plot_hidden_under(&ax, x, none, b, N, 1.5) == 0,
          "a curve that draws nothing is not hidden");
    /* a script is set at the smallest printable size, not smaller: at the legend's size (that
     * size) "x" with a subscript 1 is exactly as wide as "x1" */
    const sus_plot_style sub = sus_plot_style_of(SUS_PLOT_BLACK, 1, 0, 0, 0, "x\xe2\x82\x81"),
                         flat = sus_plot_style_of(SUS_PLOT_BLACK, 1, 0, 0, 0, "x1");
    CHECK(fabs(sus_plot_legend_width(cr, &sub, 1) - sus_plot_legend_width(cr, &flat, 1)) < 1e-9,
          "a legend's subscript prints at the smallest legible size (%g against %g pt)",
          sus_plot_legend_width(cr, &sub, 1), sus_plot_legend_width(cr, &flat, 1));
    const double r1 = sus_plot_legend_height(2) - sus_plot_legend_height(1);
    CHECK(r1 > 0.0 && fabs(sus_plot_legend_height(3) - sus_plot_legend_height(2) - r1) < 1e-12,
          "a legend grows by one line height per row (%g pt)", r1);
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    return check_summary("test_plot_layout");
}
