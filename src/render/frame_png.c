#define _POSIX_C_SOURCE 200809L
#include "frame_png.h"

#include "atomic_file.h"

#include <png.h>
#include <stdio.h>

/* No row filter and zlib's level 3: on the animation's frames (large flat areas, few colours),
 * filtering buys little and libpng's adaptive choice among all five filters costs more than the
 * compression itself; a higher level takes much longer for files only somewhat smaller. */
#define FRAME_ZLIB_LEVEL 3

/* Is every pixel of the frame opaque? */
static int opaque(const uint32_t *px, size_t n)
{
    uint32_t all = 0xff000000u;
    for (size_t i = 0; i < n; i++)
        all &= px[i];
    return (all & 0xff000000u) == 0xff000000u;
}

/* The PNG stream: libpng reports an error by longjmp, so the caller's locals stay untouched. */
static int encode(FILE *fp, const uint32_t *px, int W, int H)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_init_io(png, fp);
    png_set_compression_level(png, FRAME_ZLIB_LEVEL);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, (png_uint_32)W, (png_uint_32)H, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    /* 0xAARRGGBB in memory is B, G, R, A on a little-endian machine, A, R, G, B on a big one */
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    png_set_bgr(png);
    png_set_filler(png, 0, PNG_FILLER_AFTER);
#else
    png_set_filler(png, 0, PNG_FILLER_BEFORE);
#endif
    for (int y = 0; y < H; y++)
        png_write_row(png, (png_const_bytep)(px + (size_t)y * (size_t)W));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return 0;
}

int sus_plot_write_frame_png(const uint32_t *px, int W, int H, const char *path, char *err,
                             size_t errlen)
{
    if (!px || W <= 0 || H <= 0) {
        snprintf(err, errlen, "writing %s failed: no frame", path);
        return -1;
    }
    if (!opaque(px, (size_t)W * (size_t)H)) {
        snprintf(err, errlen, "writing %s failed: the frame is not opaque", path);
        return -1;
    }
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, errlen) != 0)
        return -1;
    if (encode(af.fp, px, W, H) != 0 || ferror(af.fp)) {
        sus_sys_atomic_file_abort(&af);
        snprintf(err, errlen, "writing %s failed", path);
        return -1;
    }
    return sus_sys_atomic_file_commit(&af, err, errlen);
}
