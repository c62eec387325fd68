// A solver header the model may not include (tests/layers/back_edge/src/model/film_probe.h).
#include "system/steady_system.h"
