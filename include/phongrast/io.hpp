// Umbrella header of phongrast::io (the phongrast::io library): meshes, scene
// files and the scene builder, images, extra outputs, sheets. The in-memory
// renderer alone is <phongrast/phongrast.hpp>.
#ifndef PHONGRAST_IO_HPP
#define PHONGRAST_IO_HPP

#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/obj_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/io/scene_load.hpp"
#include "phongrast/io/sheet.hpp"
#include "phongrast/io/text_file.hpp"

#endif  // PHONGRAST_IO_HPP
