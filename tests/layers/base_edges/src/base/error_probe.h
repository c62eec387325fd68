// A base file that includes a scene header: the base layer uses no other layer, so the
// layer check must refuse it (tests/CMakeLists.txt, layer_check_keeps_the_base_below).
#include "scene/scene_probe.h"
