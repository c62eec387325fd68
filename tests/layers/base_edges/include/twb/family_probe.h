// A public header of the base layer (named in the test's BASE_HEADERS) that includes the
// API's: refused, as from src/base.
#include "twb/api_probe.h"
