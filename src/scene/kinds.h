// The lists of kinds the scene model is made of: shapes (shapes/kinds.h) and materials
// (materials/kinds.h).
#pragma once
#include "materials/kinds.h"
#include "shapes/kinds.h"
