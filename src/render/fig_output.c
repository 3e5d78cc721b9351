#include "fig_output.h"

#include "atomic_file.h"
#include "paper_ref.h"
#include "plot.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int finish(sus_sys_atomic_file *af, const char *path)
{
    char err[512];
    if (sus_sys_atomic_file_commit(af, err, sizeof err) != 0) {
        fprintf(stderr, "error: %s\n", err);
        return -1;
    }
    (void)path;
    return 0;
}

int sus_plot_fig_write_csv(const char *path, const char *header, int ncols,
                           const double *const *cols, size_t nrows, size_t every)
{
    char err[512];
    sus_sys_atomic_file af;
    if (sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "error: %s\n", err);
        return -1;
    }
    fprintf(af.fp, "%s\n", header);
    for (size_t r = 0; r < nrows; r++)
        for (int c = 0; c < ncols; c++)
            fprintf(af.fp, c + 1 < ncols ? "%.17g," : "%.17g\n", cols[c][r * every]);
    return finish(&af, path);
}

/* A caption cites the paper by its labels, as the code does; the reader gets the published numbers
 * (paper_ref.h), each at most 2.5 times as long as its "(LABEL)" ("(TeoL)" -> "Proposition 5.1").
 */
int sus_plot_fig_write_text(const char *path, const char *text)
{
    char err[512];
    const size_t len = 3 * strlen(text) + 64;
    char *numbered = malloc(len);
    sus_sys_atomic_file af;
    if (!numbered || sus_sys_atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "error: %s\n", numbered ? err : "out of memory");
        free(numbered);
        return -1;
    }
    fputs(sus_paper_numbered(text, numbered, len), af.fp);
    free(numbered);
    return finish(&af, path);
}

const char *sus_plot_fig_path(char *buf, size_t len, const char *dir, const char *name,
                              const char *ext)
{
    snprintf(buf, len, "%s/%s.%s", dir, name, ext);
    return buf;
}

int sus_plot_fig_write_figure(const char *dir, const char *name, double width, double height,
                              void (*draw)(cairo_t *, void *), void *ctx, const char *caption)
{
    char base[4096], err[512];
    snprintf(base, sizeof base, "%s/%s", dir, name);
    if (sus_plot_write(base, width, height, draw, ctx, err, sizeof err) != 0) {
        fprintf(stderr, "error: %s: %s\n", name, err);
        return -1;
    }
    return sus_plot_fig_write_text(sus_plot_fig_path(base, sizeof base, dir, name, "txt"), caption);
}
