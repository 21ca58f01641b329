#include "comesh.h"

#include <catch2/catch.hpp>

using namespace ib;
