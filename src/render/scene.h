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
    double half[3];            /* half extents of the box along its principal axes */
    double axes[3][3];         /* principal axes (columns) in the body frame */
    double proj[16], view[16]; /* column-major, as glLoadMatrixd takes them */
    double line_scale;         /* line widths and points grow with the viewport: vh / 360, >= 1 */
} sus_plot_scene;

/* The scene's colours (RGB), so that a legend drawn beside it names them right. */
extern const double SUS_PLOT_SCENE_RGB_AXES[3];  /* e1 and e2 */
extern const double SUS_PLOT_SCENE_RGB_E3[3];    /* e3 and the trail of its tip */
extern const double SUS_PLOT_SCENE_RGB_OMEGA[3]; /* w, drawn in space: R w */
extern const double SUS_PLOT_SCENE_RGB_BOX[3];   /* the body's inertia box */
extern const double SUS_PLOT_SCENE_RGB_STAND[3]; /* the stand, the fixed point at its top */

typedef struct {
    double R[3][3];                        /* attitude */
    double w[3];                           /* body angular velocity */
    double trail[SUS_PLOT_SCENE_TRAIL][3]; /* past positions of the tip of R e3, newest last */
    int ntrail;
} sus_plot_scene_body;

/* Box from the symmetric part of I (eigenvectors by GSL), camera for a vw x vh viewport. */
int sus_plot_scene_init(sus_plot_scene *s, const sus_model *m, int vw, int vh);
/* Draws one body into the viewport (x0, y0, vw, vh) of the current context (GL's y upwards).
 * only_e3_tip: draw nothing but a marker at the tip of R e3, in pure green (for the tests). */
void sus_plot_scene_draw(const sus_plot_scene *s, const sus_plot_scene_body *b, int x0, int y0,
                         int vw, int vh, int only_e3_tip);
/* Where the body point p (body frame) lands: pixel column and row (row 0 at the top) in a
 * frame of height H, for the viewport (x0, y0, vw, vh). Returns 0, or -1 behind the camera. */
int sus_plot_scene_project(const sus_plot_scene *s, const double R[3][3], const double p[3], int x0,
                           int y0, int vw, int vh, int H, double *px, double *py);
void sus_plot_scene_body_push_trail(sus_plot_scene_body *b);

#define SUS_PLOT_SCENE_E3_TIP 1.35 /* length of the e3 arrow (the box spans about +-1) */

#endif
