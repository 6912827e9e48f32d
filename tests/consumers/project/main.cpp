// A program written the way a phongrast user writes one: render one triangle in
// memory and check two pixels. Exit status 0 only when both are right, so the
// consumer tests prove not just that it links but that the library it got works.
#include <cstdio>

#include <phongrast/phongrast.hpp>

#include "triangle_scene.hpp"

// Never called, on purpose: -Wall warns about it (-Wunused-function), and this
// file is compiled without any warning flags. If phongrast pushed its own
// warnings plus -Werror onto the projects that use it, this file would fail to build.
static int deliberately_unused_function() { return 0; }

int main() {
    const phongrast::RenderResult result =
        phongrast::render(consumer::triangle_scene(), phongrast::RenderOptions::exact());
    if (!consumer::image_is_right(result.image)) return 1;
    std::printf("phongrast %s: one triangle rendered as expected\n", PHONGRAST_VERSION_STRING);
    return 0;
}
