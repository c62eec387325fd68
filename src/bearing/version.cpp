#include "twb/version.h"

namespace twb {

const char* version() { return TWB_VERSION; }

}  // namespace twb
