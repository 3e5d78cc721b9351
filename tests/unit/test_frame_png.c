/* The animation's frame writer (src/render/frame_png.h): what it writes reads back, through an
 * independent reader (Cairo's), as the frame's colours pixel for pixel, as an 8-bit RGB PNG; a
 * frame that is not opaque is refused and leaves no file. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "frame_png.h"

#include <cairo.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define FW 37 /* odd sizes: no row falls on a convenient boundary */
#define FH 11

/* A distinct opaque colour at every pixel. */
static uint32_t colour(int x, int y)
{
    const uint32_t r = (uint32_t)(7 * x + 3 * y) & 255, g = (uint32_t)(11 * y + x * x) & 255,
                   b = (uint32_t)(x ^ (5 * y)) & 255;
    return 0xff000000u | r << 16 | g << 8 | b;
}

/* The pixels of path that differ from colour(), by Cairo's reader; -1 when it cannot read it. */
static int differing(const char *path)
{
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    int bad = -1;
    if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS && cairo_image_surface_get_width(s) == FW &&
        cairo_image_surface_get_height(s) == FH) {
        const unsigned char *d = cairo_image_surface_get_data(s);
        const int stride = cairo_image_surface_get_stride(s);
        bad = 0;
        for (int y = 0; y < FH; y++)
            for (int x = 0; x < FW; x++) {
                uint32_t p;
                memcpy(&p, d + y * stride + 4 * x, sizeof p);
                bad += (p & 0xffffffu) != (colour(x, y) & 0xffffffu);
            }
    }
    cairo_surface_destroy(s);
    return bad;
}

/* The PNG colour type, byte 25 of the file (IHDR), or -1. */
static int colour_type(const char *path)
{
    unsigned char h[26];
    FILE *fp = fopen(path, "rb");
    const int ok = fp && fread(h, 1, sizeof h, fp) == sizeof h;
    if (fp)
        fclose(fp);
    return ok ? h[25] : -1;
}

int main(void)
{
    char dir[] = "/tmp/suslov-frame-png-XXXXXX", path[64], err[256];
    if (!mkdtemp(dir)) {
        CHECK(0, "a scratch directory");
        return check_summary("test_frame_png");
    }
    snprintf(path, sizeof path, "%s/frame.png", dir);
    uint32_t px[FW * FH];
    for (int y = 0; y < FH; y++)
        for (int x = 0; x < FW; x++)
            px[y * FW + x] = colour(x, y);
    const int rc = sus_plot_write_frame_png(px, FW, FH, path, err, sizeof err);
    const int bad = differing(path);
    CHECK(rc == 0 && bad == 0,
          "a %dx%d frame of distinct colours reads back as written (write %d, %d pixels differ)",
          FW, FH, rc, bad);
    CHECK(colour_type(path) == 2, "it is an RGB PNG without alpha (colour type %d, 2)",
          colour_type(path));
    unlink(path);
    px[FW * (FH / 2) + FW / 2] &= 0xfeffffffu; /* one pixel's alpha 0xfe */
    const int rc2 = sus_plot_write_frame_png(px, FW, FH, path, err, sizeof err);
    CHECK(rc2 != 0 && access(path, F_OK) != 0 && strstr(err, "not opaque"),
          "a frame with one pixel not opaque is refused, no file left (%d: %s)", rc2, err);
    rmdir(dir);
    return check_summary("test_frame_png");
}
