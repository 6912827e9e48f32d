// Renders a phongrast::Scene with Mesa's llvmpipe through OSMesa: an
// independent implementation of ../shared/scene-format.md in OpenGL 2.1 + GLSL
// 1.20, used both as the speed baseline and as a correctness check.
//
//   camera    look-at: gluLookAt(eye, lookat, up) and glFrustum(-W/2, W/2, -H/2, H/2,
//             focal, far) with the near plane scaled down to 1e-4 x focal (same
//             x/y mapping); OpenCV: K and [R | t] written into the clip matrix;
//             orthographic: x_c, y_c over the sensor, V = -f. All computed here
//             in double from the Camera's own fields.
//   order     depth test off; triangles sorted farthest first by mean z_c
//             (stable) on the CPU and drawn in that order with one glDrawElements
//   materials one mesh (no `objects`); each face's ka, kd, ks, n by the contract's
//             precedence (scene fields, face, base), glTF colour factor, file normals
//   texture   at most one image per scene, 32-bit float, GL_LINEAR on level 0
//             with the map's wrap modes: GL_MODULATE with a separate specular
//   Gouraud   A and S per vertex in the vertex shader, interpolated
//             (perspective-correct, as GL does); the pixel is T x A + S
//   Phong     position, normal, colour, (s, t) and material interpolated, normal
//             renormalised and the formula evaluated per fragment with c x T
//   buffer    32-bit float RGBA, rows top to bottom (OSMESA_Y_UP = 0)
//
// llvmpipe's thread count comes from the LP_NUM_THREADS environment variable,
// read once when the first context is created: set it before constructing
// the first LlvmpipeRenderer in a process.
#ifndef PHONGRAST_SUPPORT_LLVMPIPE_RENDERER_HPP
#define PHONGRAST_SUPPORT_LLVMPIPE_RENDERER_HPP

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "phongrast/phongrast.hpp"

namespace phongrast::support {

/// Wall times of one llvmpipe frame, in seconds.
struct FrameTimes {
    double sort = 0.0;   ///< camera depths, stable sort, index array
    double total = 0.0;  ///< sort + index upload + clear + draw + glFinish
};

class LlvmpipeRenderer {
public:
    /// Creates the OSMesa context. Throws std::runtime_error when OSMesa fails.
    LlvmpipeRenderer();
    ~LlvmpipeRenderer();
    LlvmpipeRenderer(const LlvmpipeRenderer&) = delete;
    LlvmpipeRenderer& operator=(const LlvmpipeRenderer&) = delete;

    /// Takes a scene (normals must be present: one per vertex), sizes the
    /// colour buffer, uploads the vertex buffers and compiles the shader for its
    /// light count. Not timed: the counterpart of loading the mesh.
    /// Throws std::invalid_argument for the flat shader, lighting other than
    /// full, `objects`, and faces using two different texture images (not
    /// implemented here).
    void load(const phongrast::Scene& scene);

    /// One frame of the loaded scene, ending with glFinish.
    FrameTimes draw();

    /// The last frame as a float RGB image, row 0 at the top (values unclamped).
    phongrast::Image image() const;

    /// GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) / 2.1 Mesa 22.3.6".
    std::string description() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace phongrast::support

#endif  // PHONGRAST_SUPPORT_LLVMPIPE_RENDERER_HPP
