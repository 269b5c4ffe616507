// Included by include_2_5_6.pdl: a macro, a variable, and a file of its own.
#define LIMIT 7
#long counted
#include "procs.h"
