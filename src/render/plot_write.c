#define _POSIX_C_SOURCE 200809L
#include "plot.h"

#include "atomic_file.h"

#include <cairo-pdf.h>
#include <math.h>
#include <stdio.h>

/* Cairo writes through the atomic file (src/util/atomic_file.h): all or nothing, and no temporary
 * left behind even when the program is killed. */
static cairo_status_t write_to(void *fp, const unsigned char *data, unsigned int len)
{
    return fwrite(data, 1, len, fp) == len ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

static void paint_page(cairo_t *cr, void (*draw)(cairo_t *, void *), void *ctx)
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    draw(cr, ctx);
}

static cairo_status_t draw_pdf(FILE *fp, double width, double height,
                               void (*draw)(cairo_t *, void *), void *ctx)
{
    cairo_surface_t *pdf = cairo_pdf_surface_create_for_stream(write_to, fp, width, height);
    cairo_pdf_surface_set_metadata(pdf, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
    cairo_pdf_surface_set_metadata(pdf, CAIRO_PDF_METADATA_MOD_DATE, "2000-01-01T00:00:00Z");
    cairo_pdf_surface_set_metadata(pdf, CAIRO_PDF_METADATA_CREATOR, "suslov companion (Cairo)");
    cairo_t *cr = cairo_create(pdf);
    paint_page(cr, draw, ctx);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_finish(pdf);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_status(pdf);
    cairo_surface_destroy(pdf);
    return st;
}

/* At SUS_PLOT_PNG_DPI. */
static cairo_status_t draw_png(FILE *fp, double width, double height,
                               void (*draw)(cairo_t *, void *), void *ctx)
{
    const double s = SUS_PLOT_PNG_DPI / 72.0;
    cairo_surface_t *img =
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)ceil(width * s), (int)ceil(height * s));
    cairo_t *cr = cairo_create(img);
    cairo_scale(cr, s, s);
    paint_page(cr, draw, ctx);
    cairo_status_t st = cairo_status(cr);
    cairo_destroy(cr);
    if (st == CAIRO_STATUS_SUCCESS)
        st = cairo_surface_write_to_png_stream(img, write_to, fp);
    cairo_surface_destroy(img);
    return st;
}

typedef cairo_status_t (*page_writer)(FILE *, double, double, void (*)(cairo_t *, void *), void *);

static int write_one(const char *path, page_writer wr, double width, double height,
                     void (*draw)(cairo_t *, void *), void *ctx, char *err, size_t errlen)
{
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, errlen) != 0)
        return -1;
    const cairo_status_t st = wr(af.fp, width, height, draw, ctx);
    if (st != CAIRO_STATUS_SUCCESS) {
        sus_sys_atomic_file_abort(&af);
        snprintf(err, errlen, "writing %s failed: %s", path, cairo_status_to_string(st));
        return -1;
    }
    return sus_sys_atomic_file_commit(&af, err, errlen);
}

int sus_plot_write_surface_png(cairo_surface_t *s, const char *path, char *err, size_t errlen)
{
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, errlen) != 0)
        return -1;
    const cairo_status_t st = cairo_surface_write_to_png_stream(s, write_to, af.fp);
    if (st != CAIRO_STATUS_SUCCESS) {
        sus_sys_atomic_file_abort(&af);
        snprintf(err, errlen, "writing %s failed: %s", path, cairo_status_to_string(st));
        return -1;
    }
    return sus_sys_atomic_file_commit(&af, err, errlen);
}

int sus_plot_write(const char *base, double width, double height, void (*draw)(cairo_t *, void *),
                   void *ctx, char *err, size_t errlen)
{
    char path[4096];
    snprintf(path, sizeof path, "%s.pdf", base);
    if (write_one(path, draw_pdf, width, height, draw, ctx, err, errlen) != 0)
        return -1;
    snprintf(path, sizeof path, "%s.png", base);
    return write_one(path, draw_png, width, height, draw, ctx, err, errlen);
}
