#include "plot_internal.h"

#include <math.h>
#include <string.h>

/* A Unicode subscript or superscript of the labels (UTF-8 at s): the ASCII character it stands for
 * and its shift (-1 below, +1 above the baseline); returns its length in bytes, 0 if s is none.
 * The fonts draw these glyphs at about 0.6 of the size, too small at print size, so the plots set
 * them as ordinary characters at SCRIPT_SCALE of the size, moved off the baseline. */
#define SCRIPT_SCALE 0.8
static int script_of(const char *s, char *ascii, int *shift)
{
    static const struct {
        const char *utf8;
        char ascii;
        int shift;
    } other[] = {{"\xe2\x82\x8a", '+', -1}, {"\xe2\x82\x8b", '-', -1}, {"\xe2\x82\x96", 'k', -1},
                 {"\xe2\x82\x98", 'm', -1}, {"\xe2\x82\x99", 'n', -1}, {"\xe1\xb5\x80", 'T', 1},
                 {"\xe1\xb5\x96", 'p', 1}};
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

double sus_plot_text_width(cairo_t *cr, const char *text, double size)
{
    cairo_select_font_face(cr, SUS_PLOT_FONT, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    return label_runs(cr, 0.0, 0.0, text, size, 0);
}
