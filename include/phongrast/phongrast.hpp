// Umbrella header: everything the in-memory renderer offers (no file I/O).
#ifndef PHONGRAST_PHONGRAST_HPP
#define PHONGRAST_PHONGRAST_HPP

#include "phongrast/camera.hpp"
#include "phongrast/image.hpp"
#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"
#include "phongrast/render.hpp"
#include "phongrast/smooth_normals.hpp"
#include "phongrast/version.hpp"

#endif  // PHONGRAST_PHONGRAST_HPP
