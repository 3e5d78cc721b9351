#include "fig_output.h"

#include "atomic_file.h"

#include <stdio.h>

static int finish(atomic_file *af, const char *path)
{
    char err[512];
    if (atomic_file_commit(af, err, sizeof err) != 0) {
        fprintf(stderr, "error: %s\n", err);
        return -1;
    }
    (void)path;
    return 0;
}

int fig_write_csv(const char *path, const char *header, int ncols, const double *const *cols,
                  size_t nrows, size_t every)
{
    char err[512];
    atomic_file af;
    if (atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "error: %s\n", err);
        return -1;
    }
    fprintf(af.fp, "%s\n", header);
    for (size_t r = 0; r < nrows; r++)
        for (int c = 0; c < ncols; c++)
            fprintf(af.fp, c + 1 < ncols ? "%.17g," : "%.17g\n", cols[c][r * every]);
    return finish(&af, path);
}

int fig_write_text(const char *path, const char *text)
{
    char err[512];
    atomic_file af;
    if (atomic_file_open(&af, path, err, sizeof err) != 0) {
        fprintf(stderr, "error: %s\n", err);
        return -1;
    }
    fputs(text, af.fp);
    return finish(&af, path);
}

const char *fig_path(char *buf, size_t len, const char *dir, const char *name, const char *ext)
{
    snprintf(buf, len, "%s/%s.%s", dir, name, ext);
    return buf;
}
