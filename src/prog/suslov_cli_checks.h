/* The checks of suslov's options that need several of them (suslov_cli_checks.c), on the options
 * as the table's handlers (suslov_cli.c) stored them. */
#ifndef SUSLOV_SUSLOV_CLI_CHECKS_H
#define SUSLOV_SUSLOV_CLI_CHECKS_H

#include "suslov_cli.h"

/* The options as given, before the checks that need several of them. */
typedef struct {
    const char *method, *recon, *output;
    double eps, T, tol, every_time;
    long steps, every;
    double w0[2], inertia[9];
    int quiet, header, header_given, list, every_given, omega0_given, inertia_given;
    long sweeps;
    void (*show)(void);    /* --help, --man or --version: prints its text and exits */
    const char *show_name; /* which of them */
} suslov_args_given;

/* Fills the run's kind (steps or tolerance), its steps, model, method, stepper and
 * reconstruction into a, checking everything that can be checked before the run: bad input is
 * one line and exit 2; --reconstruct given to a method that ignores it, a warning once every
 * check has passed. g->method is not "list", and is set unless --help, --man or --version is
 * given (g->show): then every option given is checked alike, but none is required and no
 * warning is given, since no run follows. */
void suslov_args_check(suslov_args *a, const suslov_args_given *g);

#endif
