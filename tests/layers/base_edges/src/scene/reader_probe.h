// A scene file that includes the API's header at the top of include/twb: refused.
#include "twb/api_probe.h"
