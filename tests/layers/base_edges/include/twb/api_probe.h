// A public header of the top layer (the API), which may include the base layer's.
#include "twb/family_probe.h"
