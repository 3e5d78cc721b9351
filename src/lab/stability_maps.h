/* The stability map of every method at once (figures/stability), its runs split across processes
 * (workpool.h): job m * nh + i is method m's row at hs[i], nangle runs (sus_lab_stability_map).
 * The results are the same bytes whatever the number of processes: each row is computed alone,
 * from its own arguments, and lands at its own place. */
#ifndef SUS_LAB_STABILITY_MAPS_H
#define SUS_LAB_STABILITY_MAPS_H

#include "stability.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    const sus_exact *paper;
    const double *hs;
    int nh, nangle;
    int workers; /* processes (sus_sys_pool_cores() for every core); <= 1: in this one */
    /* called in this process as the row of method m at hs[i] is done, or NULL */
    void (*done)(int m, int i, void *ctx);
    void *ctx;
} sus_lab_stab_maps;

/* results[(m * nh + i) * nangle + a]: method m of the registry (sus_step_method_get), hs[i], angle
 * a, for every method. The rows are handed out longest first (by their steps, substeps and
 * implicit solves), so the cores stay busy to the end. Returns 0, or -1 with one line in err. */
int sus_lab_stability_maps(const sus_lab_stab_maps *s, sus_lab_stab_result *results, char *err,
                           size_t errlen);

/* Where each class first appears in one method's map, map[i * nangle + a] for hs[i] and start a
 * (sus_lab_stability_map; method m's rows of sus_lab_stability_maps from results + m * nh *
 * nangle): first_h[c], the smallest hs[i] at which a run on any start is of class c (INFINITY when
 * none is), and starts[c], on how many of the nangle starts a run is of class c at some h. What a
 * caption states about the map it draws comes from here, never from numbers typed beside it. */
typedef struct {
    double first_h[SUS_LAB_STAB_NCLASS];
    int starts[SUS_LAB_STAB_NCLASS];
} sus_lab_stab_onsets;
void sus_lab_stability_onsets(const sus_lab_stab_result *map, const double *hs, int nh, int nangle,
                              sus_lab_stab_onsets *o);

#ifdef __cplusplus
}
#endif

#endif
