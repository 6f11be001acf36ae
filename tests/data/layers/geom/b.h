/* the module core/a.h wrongly includes */
#include "core/a.h"
