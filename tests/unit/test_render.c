/* The off-screen renderer draws R_k, not just "an image": a marked point (the tip of e3) lands
 * where the camera's projection, computed in C, says it must, for several attitudes; and a
 * full frame has content. No display is needed (OSMesa). */
#include "check.h"
#include "gl_context.h"
#include "mat3.h"
#include "scene.h"
#include "so3.h"

#include <GL/gl.h>
#include <math.h>
#include <stdint.h>

#define W 480
#define H 270

/* centroid (column, row from the top) of the pure-green pixels; returns their count */
static int green_centroid(const uint32_t *px, double *cx, double *cy)
{
    double sx = 0.0, sy = 0.0;
    int n = 0;
    for (int r = 0; r < H; r++)
        for (int c = 0; c < W; c++) {
            const uint32_t p = px[r * W + c];
            const int R = (p >> 16) & 255, G = (p >> 8) & 255, B = p & 255;
            if (G > 200 && R < 60 && B < 60) {
                sx += c;
                sy += r;
                n++;
            }
        }
    *cx = n ? sx / n : NAN;
    *cy = n ? sy / n : NAN;
    return n;
}

int main(void)
{
    char err[128];
    sus_model m;
    sus_model_init(&m, SUS_PAPER_INERTIA, err, sizeof err);
    sus_plot_gl_context *gl = sus_plot_gl_context_create(W, H);
    CHECK(gl != NULL,
          "an off-screen OSMesa context of %dx%d with a depth buffer is created (no display)", W,
          H);
    if (!gl)
        return check_summary("test_render");
    sus_plot_scene sc;
    sus_plot_scene_init(&sc, &m, W / 3, H);
    uint32_t *px = sus_plot_gl_context_pixels(gl);
    const double rot[4][3] = {{0, 0, 0}, {0.7, 0.0, 0.0}, {0.3, -1.1, 0.4}, {-2.0, 0.5, 1.0}};
    for (int i = 0; i < 4; i++) {
        sus_plot_scene_body b = {{{0}}, {0}, {{0}}, 0};
        sus_so3_exp(rot[i], b.R);
        glClearColor(1, 1, 1, 1);
        glViewport(0, 0, W, H);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        sus_plot_scene_draw(&sc, &b, W / 3, 0, W / 3, H,
                            1); /* the middle viewport, only the e3 tip */
        glFinish();
        double cx, cy, qx, qy;
        const double tip[3] = {0.0, 0.0, SUS_PLOT_SCENE_E3_TIP};
        const int n = green_centroid(px, &cx, &cy);
        sus_plot_scene_project(&sc, b.R, tip, W / 3, 0, W / 3, H, H, &qx, &qy);
        /* a 7-pixel point: its centroid sits on the projected point to within a pixel */
        CHECK(n > 10 && hypot(cx - qx, cy - qy) < 1.5,
              "e3 tip of R = exp(%.1f, %.1f, %.1f)^ drawn at (%.2f, "
              "%.2f), projected (%.2f, %.2f) (%d pixels)",
              rot[i][0], rot[i][1], rot[i][2], cx, cy, qx, qy, n);
    }
    /* a full frame: not blank, not one colour */
    sus_plot_scene_body b = {{{0}}, {0.4, 0.5, 0.0}, {{0}}, 0};
    sus_so3_exp(rot[2], b.R);
    sus_plot_scene_body_push_trail(&b);
    glClearColor(0.97f, 0.97f, 0.95f, 1.0f);
    glViewport(0, 0, W, H);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    sus_plot_scene_draw(&sc, &b, 0, 0, W / 3, H, 0);
    glFinish();
    /* each element of the scene is there in its colour: the box (blue > red), e3 (red), w (orange)
     */
    int changed = 0, box = 0, red = 0, orange = 0;
    for (int i = 0; i < W * H; i++) {
        const int R = (px[i] >> 16) & 255, G = (px[i] >> 8) & 255, B = px[i] & 255;
        changed += px[i] != px[0];
        box += B > R + 40;
        red += R > 150 && G < 80 && B < 80;
        orange += R > 200 && G > 100 && G < 200 && B < 60;
    }
    CHECK(changed > W * H / 50 && box > 100 && red > 10 && orange > 10,
          "a full frame has content: %d pixels off the background; "
          "box %d, e3 (red) %d, w (orange) %d pixels",
          changed, box, red, orange);
    sus_plot_gl_context_destroy(gl);
    return check_summary("test_render");
}
