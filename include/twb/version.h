// The version of the twb library a program runs with (the package's, e.g. "0.1.0").
#pragma once

namespace twb {

const char* version();

}  // namespace twb
