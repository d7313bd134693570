// Triangle meshes (shapes/mesh_data.h): the loaders of scene/ fill them; a Mesh shape
// places one (shapes/mesh.h).
#pragma once
#include "shapes/mesh_data.h"
