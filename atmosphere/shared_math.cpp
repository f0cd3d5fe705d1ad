// The shared math is header-only (internal linkage, see shared_math.h);
// compiling the header on its own keeps it self-contained.
#include "atmosphere/shared_math.h"
