/* The figures' legend notes: sus_plot_hidden_under says a curve hides under another exactly when
 * every point it draws lies within the tolerance of the other's on the page. On log axes of 10
 * points per decade, a factor 1 + 1e-3 moves a point by 10 log10(1.001) = 0.004 pt (hidden at
 * 1.5 pt) and a factor 1.5 by 1.8 pt (not hidden); a point the other curve does not draw, or a
 * curve that draws nothing, is never hidden. No text, scripts included, is set below the size that
 * prints at 7 pt. A band fills what lies between its two curves and nothing beyond them. */
#include "check.h"
#include "plot.h"

#include <math.h>
#include <stdint.h>

#define N 8

/* Whether the pixel at page point (x, y) is black, the band's colour on a white page. */
static int dark(cairo_surface_t *s, double x, double y)
{
    cairo_surface_flush(s);
    const unsigned char *px = cairo_image_surface_get_data(s);
    const uint32_t v =
        *(const uint32_t *)(px + (int)y * cairo_image_surface_get_stride(s) + 4 * (int)x);
    return (v & 0xffffff) == 0;
}

/* The band between 1e-6 and 1e-4 on log axes at page (10, 10), 150 x 100 points, of x in
 * [1e-3, 1] and y in [1e-10, 1]: x = 10^a lies at 10 + 50 (a + 3), y = 10^b at 10 - 10 b. Filled
 * at (1e-2, 1e-5), page (60, 60); white at 1e-2 and 1e-8 above and below it, page y 30 and 90; a
 * NaN on the upper curve at x = 1 leaves that point out, so the band ends at x = 0.1 (page 110)
 * and page (145, 60), x = 0.5, stays white. */
static void band(cairo_t *cr, cairo_surface_t *s)
{
    sus_plot_axes ax;
    sus_plot_axes_init(&ax, cr, 10, 10, 150, 100, 1e-3, 1.0, 1e-10, 1.0, 1, 1);
    const double x[4] = {1e-3, 1e-2, 1e-1, 1.0}, lo[4] = {1e-6, 1e-6, 1e-6, 1e-6},
                 hi[4] = {1e-4, 1e-4, 1e-4, NAN};
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    sus_plot_band(&ax, x, lo, hi, 4, (const double[3]){0, 0, 0});
    CHECK(dark(s, 60, 60), "a band fills between its curves");
    CHECK(!dark(s, 60, 30) && !dark(s, 60, 90), "and nothing above or below them");
    CHECK(!dark(s, 145, 60), "a point it cannot draw is left out: the band ends before it");
}

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
    band(cr, s);
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    return check_summary("test_plot_layout");
}
