/* The suslov command's options: one table (suslov_cli.c) from which come the parser, --help and
 * the manual page (cli_options.h), and everything that can be checked before a run. */
#ifndef SUSLOV_SUSLOV_CLI_H
#define SUSLOV_SUSLOV_CLI_H

#include "model.h"
#include "registry.h"

#include <stdio.h>

typedef struct {
    const sus_step_method *method;   /* NULL for exact */
    const sus_stepper_type *stepper; /* the step the run takes: the method's, or --sweeps' */
    int sweeps;                      /* --sweeps N, or 0 */
    sus_recon recon;
    const char *output; /* NULL or "-" for stdout */
    double eps;
    long steps, every;
    double tol, t_end,
        every_time; /* tol > 0: a tolerance-driven run (t_end: the final time of any run) */
    double w0[2], inertia[9];
    int quiet, header;
    sus_model model;
} suslov_args;

/* The step budget of a --tol run (sus_tol_config.max_steps): its step count is known only as it
 * runs and grows with |w0| T, so input such as |w0| = 1e150 would otherwise run for ages. */
#define SUSLOV_TOL_MAX_STEPS 1000000L

/* Parses and checks everything that can be checked before the run (bad input: one line, exit
 * 2); --help, --version, --man and --method list print and exit 0 (1 if stdout fails), the first
 * three after the same checks of every option given (suslov_args_check). */
void suslov_args_parse(suslov_args *a, int argc, char **argv);
/* The #-comment lines before the CSV header: version, command line, method, eps, body, w0,
 * units. */
void suslov_args_header(const suslov_args *a, int argc, char **argv, FILE *fp);
/* The commit built from (git describe), or "unknown". */
const char *suslov_version(void);

#endif
