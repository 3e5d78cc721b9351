/* The one place that knows how an off-screen OpenGL context is made (OSMesa; Mesa drops it after
 * 25.0 in favour of EGL surfaceless, so only this file would change). The buffer is BGRA, laid
 * out like Cairo's CAIRO_FORMAT_ARGB32 on little-endian machines, rows top-down. */
#ifndef SUS_PLOT_GL_CONTEXT_H
#define SUS_PLOT_GL_CONTEXT_H

#include <stdint.h>

typedef struct sus_plot_gl_context sus_plot_gl_context;

/* A width x height context with a 24-bit depth buffer, made current; NULL on failure. */
sus_plot_gl_context *sus_plot_gl_context_create(int width, int height);
uint32_t *sus_plot_gl_context_pixels(
    sus_plot_gl_context *c); /* width * height BGRA words, row 0 at the top */
void sus_plot_gl_context_destroy(sus_plot_gl_context *c);

#endif
