/* The commit suslov was built from, for --version, --man and the output's header: the one object
 * the Makefile rebuilds when the commit changes. */
#include "suslov_cli.h"

#ifndef SUSLOV_VERSION
#define SUSLOV_VERSION "unknown" /* the Makefile passes the git commit; a tarball has none */
#endif

const char *suslov_version(void) { return SUSLOV_VERSION; }
