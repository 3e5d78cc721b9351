#include "scene.h"

#include "mat3.h"

#include <GL/gl.h>
#include <gsl/gsl_eigen.h>
#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- camera: column-major 4x4 matrices, as OpenGL keeps them ---- */

static void perspective(double m[16], double fovy_deg, double aspect, double znear, double zfar)
{
    const double f = 1.0 / tan(0.5 * fovy_deg * PI / 180.0);
    memset(m, 0, 16 * sizeof(double));
    m[0] = f / aspect;
    m[5] = f;
    m[10] = (zfar + znear) / (znear - zfar);
    m[11] = -1.0;
    m[14] = 2.0 * zfar * znear / (znear - zfar);
}

static void look_at(double m[16], const double eye[3], const double up[3])
{
    double f[3] = {-eye[0], -eye[1], -eye[2]}, s[3], u[3]; /* looking at the origin */
    const double nf = sus_vec3_norm(f);
    for (int i = 0; i < 3; i++)
        f[i] /= nf;
    sus_vec3_cross(s, f, up);
    const double ns = sus_vec3_norm(s);
    for (int i = 0; i < 3; i++)
        s[i] /= ns;
    sus_vec3_cross(u, s, f);
    memset(m, 0, 16 * sizeof(double));
    for (int i = 0; i < 3; i++) {
        m[4 * i + 0] = s[i];
        m[4 * i + 1] = u[i];
        m[4 * i + 2] = -f[i];
    }
    m[12] = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
    m[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    m[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    m[15] = 1.0;
}

static void mul4v(const double m[16], const double v[4], double out[4])
{
    for (int r = 0; r < 4; r++)
        out[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3];
}

/* A 3x3 row-major matrix as a column-major 4x4 one, for glMultMatrixd. */
static void gl_matrix(const double A[3][3], double m[16])
{
    memset(m, 0, 16 * sizeof(double));
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            m[4 * c + r] = A[r][c];
    m[15] = 1.0;
}

int sus_plot_scene_init(sus_plot_scene *s, const sus_model *mdl, int vw, int vh)
{
    /* principal axes and moments of the symmetric part of I */
    gsl_matrix *S = gsl_matrix_alloc(3, 3), *V = gsl_matrix_alloc(3, 3);
    gsl_vector *ev = gsl_vector_alloc(3);
    gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc(3);
    if (!S || !V || !ev || !w)
        return -1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            gsl_matrix_set(S, i, j, 0.5 * (mdl->I[i][j] + mdl->I[j][i]));
    gsl_eigen_symmv(S, ev, V, w);
    gsl_eigen_symmv_sort(ev, V, GSL_EIGEN_SORT_VAL_ASC);
    double mom[3], hmax = 0.0;
    for (int i = 0; i < 3; i++) {
        mom[i] = gsl_vector_get(ev, i);
        for (int j = 0; j < 3; j++)
            s->axes[j][i] = gsl_matrix_get(V, j, i);
    }
    if (sus_mat3_det(s->axes) < 0) /* keep the frame right-handed */
        for (int j = 0; j < 3; j++)
            s->axes[j][2] = -s->axes[j][2];
    /* a uniform box with half extents a_i has I_i proportional to a_j^2 + a_k^2 */
    for (int i = 0; i < 3; i++) {
        const double q = mom[(i + 1) % 3] + mom[(i + 2) % 3] - mom[i];
        s->half[i] = sqrt(q > 0 ? q : 0.0);
        hmax = fmax(hmax, s->half[i]);
    }
    for (int i = 0; i < 3; i++)
        s->half[i] = s->half[i] / hmax;
    gsl_eigen_symmv_free(w);
    gsl_vector_free(ev);
    gsl_matrix_free(V);
    gsl_matrix_free(S);
    const double eye[3] = {5.95, 4.55, 4.0},
                 up[3] = {
                     0.0, 0.0,
                     1.0}; /* far enough that a 1/3-wide viewport holds the body and its arrows */
    perspective(s->proj, 38.0, (double)vw / (double)vh, 0.5, 20.0);
    s->line_scale = vh > 360 ? vh / 360.0 : 1.0;
    look_at(s->view, eye, up);
    return 0;
}

int sus_plot_scene_project(const sus_plot_scene *s, const double R[3][3], const double p[3], int x0,
                           int y0, int vw, int vh, int H, double *px, double *py)
{
    double q[3], a[4], b[4], clip[4];
    sus_mat3_vec(q, R, p);
    const double v[4] = {q[0], q[1], q[2], 1.0};
    mul4v(s->view, v, a);
    memcpy(b, a, sizeof b);
    mul4v(s->proj, b, clip);
    if (clip[3] <= 0.0)
        return -1;
    const double wx = x0 + 0.5 * (clip[0] / clip[3] + 1.0) * vw;
    const double wy = y0 + 0.5 * (clip[1] / clip[3] + 1.0) * vh;
    *px = wx - 0.5;     /* pixel column whose centre is at wx */
    *py = H - wy - 0.5; /* row counted from the top */
    return 0;
}

void sus_plot_scene_body_push_trail(sus_plot_scene_body *b)
{
    const double e3[3] = {0.0, 0.0, SUS_PLOT_SCENE_E3_TIP};
    double tip[3];
    sus_mat3_vec(tip, b->R, e3);
    if (b->ntrail == SUS_PLOT_SCENE_TRAIL) {
        memmove(b->trail, b->trail + 1, (SUS_PLOT_SCENE_TRAIL - 1) * sizeof b->trail[0]);
        b->ntrail--;
    }
    memcpy(b->trail[b->ntrail++], tip, sizeof tip);
}

static void box(void)
{
    static const double n[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        const int a = f / 2, b = (a + 1) % 3, c = (a + 2) % 3;
        const double sgn = n[f][a];
        glNormal3dv(n[f]);
        static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; k++) {
            const int kk = sgn > 0 ? k : 3 - k; /* counter-clockwise seen from outside */
            double v[3];
            v[a] = sgn;
            v[b] = corner[kk][0];
            v[c] = corner[kk][1];
            glVertex3dv(v);
        }
    }
    glEnd();
}

const double SUS_PLOT_SCENE_RGB_AXES[3] = {0.30, 0.30, 0.30};
const double SUS_PLOT_SCENE_RGB_E3[3] = {0.85, 0.10, 0.10};
const double SUS_PLOT_SCENE_RGB_OMEGA[3] = {0.95, 0.60, 0.05};
const double SUS_PLOT_SCENE_RGB_BOX[3] = {0.55, 0.70, 0.90};
const double SUS_PLOT_SCENE_RGB_STAND[3] = {0.15, 0.15, 0.15};

static void arrow(const double from[3], const double to[3], double width)
{
    glLineWidth((float)width);
    glBegin(GL_LINES);
    glVertex3dv(from);
    glVertex3dv(to);
    glEnd();
    glPointSize((float)(2.2 * width));
    glBegin(GL_POINTS);
    glVertex3dv(to);
    glEnd();
}

/* The tip of e3 alone, as a green point: what the animation's test finds in the frame. */
static void draw_e3_tip(const double m[16])
{
    const double tip[3] = {0.0, 0.0, SUS_PLOT_SCENE_E3_TIP};
    glDisable(GL_LIGHTING);
    glMultMatrixd(m);
    glColor3d(0.0, 1.0, 0.0);
    glPointSize(7.0f);
    glBegin(GL_POINTS);
    glVertex3dv(tip);
    glEnd();
}

/* The fixed point and the stand it hangs from (space frame). */
static void draw_stand(const sus_plot_scene *s)
{
    const double origin[3] = {0, 0, 0}, base[3] = {0.0, 0.0, -1.9};
    glDisable(GL_LIGHTING);
    glColor3dv(SUS_PLOT_SCENE_RGB_STAND);
    arrow(origin, base, 3.0 * s->line_scale);
    glPointSize((float)(9.0 * s->line_scale));
    glBegin(GL_POINTS);
    glVertex3dv(origin);
    glEnd();
}

/* The trail of the tip of e3, fading with age. The frame's alpha must stay 1: Cairo reads the
 * buffer as premultiplied ARGB, where a colour above its alpha turns into garbage. */
static void draw_trail(const sus_plot_scene *s, const sus_plot_scene_body *b)
{
    const double *c = SUS_PLOT_SCENE_RGB_E3;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glLineWidth((float)(2.0 * s->line_scale));
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < b->ntrail; i++) {
        glColor4d(c[0], c[1], c[2], (double)(i + 1) / b->ntrail);
        glVertex3dv(b->trail[i]);
    }
    glEnd();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_BLEND);
}

/* w in the space frame, R w. */
static void draw_omega(const sus_plot_scene *s, const sus_plot_scene_body *b)
{
    const double origin[3] = {0, 0, 0};
    double ws[3], wtip[3];
    sus_mat3_vec(ws, b->R, b->w);
    for (int i = 0; i < 3; i++)
        wtip[i] = 2.0 * ws[i];
    glColor3dv(SUS_PLOT_SCENE_RGB_OMEGA);
    arrow(origin, wtip, 3.0 * s->line_scale);
}

/* The body: its axes e1, e2, e3 as arrows and its inertia box, lit by a light fixed in space;
 * the modelview holds the body's frame m on return. */
static void draw_body(const sus_plot_scene *s, const double m[16])
{
    const double origin[3] = {0, 0, 0};
    glMultMatrixd(m);
    const double e[3][3] = {{1.3, 0, 0}, {0, 1.3, 0}, {0, 0, SUS_PLOT_SCENE_E3_TIP}};
    glColor3dv(SUS_PLOT_SCENE_RGB_AXES);
    arrow(origin, e[0], 2.5 * s->line_scale);
    arrow(origin, e[1], 2.5 * s->line_scale);
    glColor3dv(SUS_PLOT_SCENE_RGB_E3);
    arrow(origin, e[2], 3.5 * s->line_scale);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    const float light[4] = {0.4f, 0.3f, 1.0f, 0.0f}, amb[4] = {0.35f, 0.35f, 0.35f, 1.0f};
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glPushMatrix();
    glLoadMatrixd(s->view); /* the light is fixed in space */
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glPopMatrix();
    double A[16];
    gl_matrix(s->axes, A);
    glMultMatrixd(A);
    glScaled(s->half[0] * 0.8, s->half[1] * 0.8, s->half[2] * 0.8);
    glColor3dv(SUS_PLOT_SCENE_RGB_BOX);
    box();
    glDisable(GL_LIGHTING);
}

void sus_plot_scene_draw(const sus_plot_scene *s, const sus_plot_scene_body *b, int x0, int y0,
                         int vw, int vh, int only_e3_tip)
{
    double m[16];
    glViewport(x0, y0, vw, vh);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixd(s->proj);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(s->view);
    gl_matrix(b->R, m);
    if (only_e3_tip) {
        draw_e3_tip(m);
        return;
    }
    draw_stand(s);
    draw_trail(s, b);
    draw_omega(s, b);
    draw_body(s, m);
}
