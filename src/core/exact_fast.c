#include "exact_fast.h"

int sus_exact_fast_init(sus_exact_fast *f, const sus_exact *ex)
{
    if (!f)
        return -1;
    *f = (sus_exact_fast){
        .M = {{NAN, NAN}, {NAN, NAN}}, .c = {NAN, NAN}, .s0 = NAN, .ks = NAN, .cs = NAN, .c0 = NAN};
    if (!ex || !ex->model)
        return -1;
    sus_exact_limit(ex, f->winf);
    if (ex->fixed) { /* w stays w0: M = 0, c = w0, s anything finite */
        *f = (sus_exact_fast){
            .c = {ex->w0[0], ex->w0[1]}, .winf = {ex->w0[0], ex->w0[1]}, .c0 = ex->c0, .fixed = 1};
        return 0;
    }
    /* M = sigma r L^{-T} Rot(beta), L^{-T} = [[1/l11, -l21/(l11 l22)], [0, 1/l22]] */
    const double g = ex->sigma * ex->r, cb = ex->cb, sb = ex->sb;
    const double R[2][2] = {{g * cb, -g * sb}, {g * sb, g * cb}};
    for (int j = 0; j < 2; j++) {
        f->M[1][j] = R[1][j] / ex->l22;
        f->M[0][j] = (R[0][j] - ex->l21 * f->M[1][j]) / ex->l11;
    }
    f->c[0] = f->c[1] = 0.0;
    f->s0 = ex->s0;
    f->ks = ex->sigma * ex->k;
    f->cs = ex->sigma * ex->cmax;
    f->c0 = ex->c0;
    return 0;
}
