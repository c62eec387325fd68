// Every layer may include the base layer's headers, in src/base and at the top of
// include/twb: nothing here is refused.
#include "base/error_probe.h"
#include "twb/family_probe.h"
