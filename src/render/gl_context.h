/* The one place that knows how an off-screen OpenGL context is made (OSMesa; Mesa drops it after
 * 25.0 in favour of EGL surfaceless, so only this file would change). The buffer is BGRA, laid
 * out like Cairo's CAIRO_FORMAT_ARGB32 on little-endian machines, rows top-down. */
#ifndef SUSLOV_GL_CONTEXT_H
#define SUSLOV_GL_CONTEXT_H

#include <stdint.h>

typedef struct gl_context gl_context;

/* A width x height context with a 24-bit depth buffer, made current; NULL on failure. */
gl_context *gl_context_create(int width, int height);
uint32_t *gl_context_pixels(gl_context *c); /* width * height BGRA words, row 0 at the top */
void gl_context_destroy(gl_context *c);

#endif
