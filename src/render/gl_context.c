#include "gl_context.h"

#include <GL/osmesa.h>
#include <stdlib.h>

struct sus_plot_gl_context {
    OSMesaContext ctx;
    uint32_t *pixels;
    int width, height;
};

sus_plot_gl_context *sus_plot_gl_context_create(int width, int height)
{
    sus_plot_gl_context *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    c->width = width;
    c->height = height;
    c->pixels = calloc((size_t)width * (size_t)height, sizeof *c->pixels);
    /* depthBits = 24: with 0 there is no depth buffer and the depth test silently passes */
    c->ctx = OSMesaCreateContextExt(OSMESA_BGRA, 24, 0, 0, NULL);
    if (!c->pixels || !c->ctx ||
        !OSMesaMakeCurrent(c->ctx, c->pixels, GL_UNSIGNED_BYTE, width, height)) {
        sus_plot_gl_context_destroy(c);
        return NULL;
    }
    OSMesaPixelStore(OSMESA_Y_UP, 0); /* row 0 at the top, as image files want it */
    return c;
}

uint32_t *sus_plot_gl_context_pixels(sus_plot_gl_context *c) { return c->pixels; }

void sus_plot_gl_context_destroy(sus_plot_gl_context *c)
{
    if (!c)
        return;
    if (c->ctx)
        OSMesaDestroyContext(c->ctx);
    free(c->pixels);
    free(c);
}
