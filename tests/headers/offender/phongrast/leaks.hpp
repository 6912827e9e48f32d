// Test fixture for tests/headers/check_public_includes.cmake: a public header that
// wrongly includes a private dependency. Never compiled; the check must flag line 4.
#pragma once
#include <OpenImageIO/imageio.h>
