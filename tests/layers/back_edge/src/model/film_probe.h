// A model file that includes a solver header: the layer check must refuse it
// (tests/CMakeLists.txt, layer_check_refuses_a_back_edge).
#include "solver/newton_probe.h"
