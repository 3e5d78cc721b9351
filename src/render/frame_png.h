/* The animation's frames as PNG files, written for speed: a frame is written hundreds of times a
 * run and never committed, so it takes the fast settings of frame_png.c, where Cairo's PNG writer
 * (which the committed figures keep) spends much of the animation's time on adaptive row filters
 * and compression. */
#ifndef SUS_PLOT_FRAME_PNG_H
#define SUS_PLOT_FRAME_PNG_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Writes the W x H frame px (rows of W pixels, Cairo's ARGB32: 0xAARRGGBB in native order) to path
 * as an 8-bit RGB PNG, through the atomic file (complete or not at all). The frame must be
 * opaque (every alpha 0xff): its alpha is dropped, and a pixel that is not opaque is refused, as
 * its premultiplied colour would be written darker than it is. Returns 0, or -1 with a message in
 * err. Deterministic: the same frame gives the same bytes. */
int sus_plot_write_frame_png(const uint32_t *px, int W, int H, const char *path, char *err,
                             size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
