/* sus_lab_stability_onsets (src/lab/stability_maps.h), what figure_stability's caption states about
 * its map, on maps built by hand whose answers are known by construction:
 *   - each class's first h is the least h at which any start has it, whichever row holds it (the
 *     same map with its rows in reverse order gives the same answers);
 *   - its starts count each start once however many of its runs have the class;
 *   - a class no run has: INFINITY and 0 starts. */
#include "check.h"
#include "stability_maps.h"

#include <math.h>

#define NH 4
#define NA 3

/* Start a's class at row i of the map; rows ascending in h: 0.1, 1, 10, 100. */
static const int CLS[NA][NH] = {
    {SUS_LAB_STAB_GOOD, SUS_LAB_STAB_GOOD, SUS_LAB_STAB_WRONG_LIMIT, SUS_LAB_STAB_BLOWUP},
    {SUS_LAB_STAB_GOOD, SUS_LAB_STAB_WRONG_LIMIT, SUS_LAB_STAB_WRONG_LIMIT,
     SUS_LAB_STAB_WRONG_LIMIT},
    {SUS_LAB_STAB_GOOD, SUS_LAB_STAB_GOOD, SUS_LAB_STAB_GOOD, SUS_LAB_STAB_REGULARITY}};

static void check_onsets(int reversed)
{
    const double up[NH] = {0.1, 1.0, 10.0, 100.0};
    double hs[NH];
    sus_lab_stab_result map[NH * NA] = {{0}};
    for (int i = 0; i < NH; i++) {
        const int row = reversed ? NH - 1 - i : i;
        hs[i] = up[row];
        for (int a = 0; a < NA; a++)
            map[i * NA + a].cls = CLS[a][row];
    }
    sus_lab_stab_onsets o;
    sus_lab_stability_onsets(map, hs, NH, NA, &o);
    const double want_h[SUS_LAB_STAB_NCLASS] = {0.1, 1.0, 100.0, INFINITY, 100.0};
    const int want_starts[SUS_LAB_STAB_NCLASS] = {3, 2, 1, 0, 1};
    for (int c = 0; c < SUS_LAB_STAB_NCLASS; c++)
        CHECK(o.first_h[c] == want_h[c] && o.starts[c] == want_starts[c],
              "%s rows: %s first at h = %g on %d starts (by construction: %g on %d)",
              reversed ? "descending" : "ascending", SUS_LAB_STAB_NAMES[c], o.first_h[c],
              o.starts[c], want_h[c], want_starts[c]);
}

int main(void)
{
    check_onsets(0);
    check_onsets(1);
    return check_summary("test_stability_onsets");
}
