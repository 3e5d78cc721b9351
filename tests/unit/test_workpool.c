/* The worker pool (src/util/workpool.h) and the stability map split across it
 * (src/lab/stability_maps.h):
 *   - results are the same bytes for 1, 2, 3 and 7 processes and for any hand-out order, each
 *     job's result at its own place, and the parent hears of every job exactly once;
 *   - a worker that dies fails the run with one line naming its job, and leaves no process behind
 *     (no child left to wait for);
 *   - the stability map of every method on a small grid (h = 0.01, 1, 100; 4 starts) is the same
 *     in one process, in two and in three, and the same as sus_lab_stability_map row by row in this
 *     process, every field and every bit: so figure_stability writes the same files for any
 *     --jobs. */
#include "check.h"
#include "model.h"
#include "stability_maps.h"
#include "workpool.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define NJOBS 50

typedef struct {
    int calls[NJOBS];
    pid_t parent;
    int die_at; /* a job whose worker dies (-1: none) */
} pool_ctx;

/* A job whose result depends on its number only, through rounding-sensitive arithmetic. */
static void job(int j, void *result, void *vctx)
{
    const pool_ctx *c = vctx;
    double *r = result, s = 0.0;
    if (j == c->die_at && getpid() != c->parent)
        _exit(7);
    for (int k = 1; k <= 1000; k++)
        s += sin(j * 0.37 + k) / k;
    r[0] = s, r[1] = exp(-j * 0.1), r[2] = j;
}

static void done(int j, void *vctx)
{
    pool_ctx *c = vctx;
    c->calls[j]++;
}

/* Runs the jobs with `workers` processes (order reversed when `reversed`) into r; the number of
 * jobs the parent heard of other than exactly once in *bad_calls. */
static int run(int workers, int reversed, double r[NJOBS][3], int *bad_calls)
{
    int order[NJOBS];
    pool_ctx c = {.parent = getpid(), .die_at = -1};
    for (int j = 0; j < NJOBS; j++)
        order[j] = reversed ? NJOBS - 1 - j : j;
    const sus_sys_pool p = {NJOBS, order, sizeof r[0], r, workers, job, done, &c};
    char err[256];
    const int rc = sus_sys_pool_run(&p, err, sizeof err);
    *bad_calls = 0;
    for (int j = 0; j < NJOBS; j++)
        *bad_calls += c.calls[j] != 1;
    return rc;
}

static void same_bytes(void)
{
    static const int W[4] = {1, 2, 3, 7};
    double ref[NJOBS][3], r[NJOBS][3];
    int bad, differ = 0, failed = 0, calls = 0;
    failed += run(1, 0, ref, &bad) != 0;
    calls += bad;
    for (int i = 0; i < 4; i++)
        for (int rev = 0; rev < 2; rev++) {
            memset(r, 0xff, sizeof r);
            failed += run(W[i], rev, r, &bad) != 0;
            calls += bad;
            differ += memcmp(r, ref, sizeof r) != 0;
        }
    CHECK(failed == 0 && differ == 0 && calls == 0,
          "%d jobs with 1, 2, 3, 7 processes, handed out in order and reversed: %d runs failed, %d "
          "differ from one process in a byte, %d jobs reported other than once",
          NJOBS, failed, differ, calls);
}

static void worker_dies(void)
{
    double r[NJOBS][3];
    pool_ctx c = {.parent = getpid(), .die_at = 13};
    const sus_sys_pool p = {NJOBS, NULL, sizeof r[0], r, 2, job, done, &c};
    char err[256] = "";
    const int rc = sus_sys_pool_run(&p, err, sizeof err);
    errno = 0;
    const int left = waitpid(-1, NULL, WNOHANG) != -1 || errno != ECHILD;
    CHECK(rc == -1 && strstr(err, "job 13") && !left,
          "a worker that dies at job 13: rc %d (-1), \"%s\" (names job 13), %s", rc, err,
          left ? "a child left behind" : "no child left");
}

/* Field by field (a struct's padding is no result), doubles bit for bit. */
static int same_results(const sus_lab_stab_result *a, const sus_lab_stab_result *b, int n)
{
    for (int k = 0; k < n; k++)
        if (a[k].cls != b[k].cls || a[k].step != b[k].step ||
            memcmp(&a[k].final_err, &b[k].final_err, sizeof a[k].final_err) ||
            memcmp(a[k].w_fail, b[k].w_fail, sizeof a[k].w_fail))
            return 0;
    return 1;
}

static void maps_same(void)
{
    sus_model m;
    sus_exact paper;
    sus_model_init(&m, SUS_PAPER_INERTIA, NULL, 0);
    sus_exact_init(&paper, &m, SUS_PAPER_OMEGA0);
    enum { NH = 3, NA = 4 };
    const double hs[NH] = {0.01, 1.0, 100.0};
    const int nm = sus_step_method_count(), n = nm * NH * NA;
    sus_lab_stab_result *one = calloc((size_t)n, sizeof *one),
                        *two = calloc((size_t)n, sizeof *one),
                        *three = calloc((size_t)n, sizeof *one),
                        *direct = calloc((size_t)n, sizeof *one);
    if (!one || !two || !three || !direct) {
        CHECK(0, "out of memory");
        return;
    }
    sus_lab_stab_maps s = {&paper, hs, NH, NA, 1, NULL, NULL};
    char err[256];
    int rc = sus_lab_stability_maps(&s, one, err, sizeof err);
    s.workers = 2;
    rc |= sus_lab_stability_maps(&s, two, err, sizeof err);
    s.workers = 3;
    rc |= sus_lab_stability_maps(&s, three, err, sizeof err);
    for (int k = 0; k < nm; k++)
        for (int i = 0; i < NH; i++)
            sus_lab_stability_map(&paper, sus_step_method_get(k)->type, &hs[i], 1, NA,
                                  &direct[(k * NH + i) * NA]);
    CHECK(rc == 0 && same_results(one, two, n) && same_results(one, three, n) &&
              same_results(one, direct, n),
          "the stability map of %d methods, h = 0.01, 1, 100, %d starts: one process, two, three, "
          "and the rows by hand are the same bytes (rc %d)",
          nm, NA, rc);
    free(one), free(two), free(three), free(direct);
}

int main(void)
{
    same_bytes();
    worker_dies();
    maps_same();
    return check_summary("test_workpool");
}
