/* an include that runs up the layers, for lint_layers_catches */
#include "geom/b.h"
