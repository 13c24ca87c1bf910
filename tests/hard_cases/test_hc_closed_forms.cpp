#include <doctest/doctest.h>
#include "hc_util.h"
