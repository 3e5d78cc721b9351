/* The attitude scene: a box with the principal axes and relative extents of the symmetric part
 * of the inertia tensor, the fixed point it turns about, its body axes e1, e2 and e3 (e3, the
 * direction along which w must vanish, set apart in red), the body angular velocity w as an
 * arrow, and a fading trail of the tip of e3. Fixed-function OpenGL with the camera matrices
 * computed here, so that sus_plot_scene_project tells exactly where a point of the body lands. */
#ifndef SUS_PLOT_SCENE_H
#define SUS_PLOT_SCENE_H

#include "model.h"

#define SUS_PLOT_SCENE_TRAIL 90

typedef struct {
    double half[3];          /* half extents of the box along its principal axes */
    double axes[3][3];       /* principal axes (columns) in the body frame */
    double proj[16], view[16]; /* column-major, as glLoadMatrixd takes them */
} sus_plot_scene;

typedef struct {
    double R[3][3];                /* attitude */
    double w[3];                   /* body angular velocity */
    double trail[SUS_PLOT_SCENE_TRAIL][3];  /* past positions of the tip of R e3, newest last */
    int ntrail;
} sus_plot_scene_body;

/* Box from the symmetric part of I (eigenvectors by GSL), camera for a vw x vh viewport. */
int sus_plot_scene_init(sus_plot_scene *s, const sus_model *m, int vw, int vh);
/* Draws one body into the viewport (x0, y0, vw, vh) of the current context (GL's y upwards).
 * only_e3_tip: draw nothing but a marker at the tip of R e3, in pure green (for the tests). */
void sus_plot_scene_draw(const sus_plot_scene *s, const sus_plot_scene_body *b, int x0, int y0, int vw,
                         int vh, int only_e3_tip);
/* Where the body point p (body frame) lands: pixel column and row (row 0 at the top) in a
 * frame of height H, for the viewport (x0, y0, vw, vh). Returns 0, or -1 behind the camera. */
int sus_plot_scene_project(const sus_plot_scene *s, const double R[3][3], const double p[3], int x0, int y0,
                           int vw, int vh, int H, double *px, double *py);
void sus_plot_scene_body_push_trail(sus_plot_scene_body *b);

#define SUS_PLOT_SCENE_E3_TIP 1.35  /* length of the e3 arrow (the box spans about +-1) */

#endif
